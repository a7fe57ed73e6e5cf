// PMSIS-style performance counters of one core. The core keeps free-running event totals; a
// counter is the total accumulated between start and stop since the last reset, reported only
// for events enabled by the configuration mask.
#pragma once

#include <array>
#include <cstdint>

#include "../../runtime/gap8_regs.h"

namespace gap8 {

using EventTotals = std::array<uint64_t, GAP8_EVT_COUNT>;

class PerfCounters {
 public:
  void Configure(uint32_t mask) { mask_ = mask; }
  void Reset(const EventTotals& now) {
    accumulated_.fill(0);
    snapshot_ = now;
  }
  void Start(const EventTotals& now) {
    if (!running_) snapshot_ = now;
    running_ = true;
  }
  void Stop(const EventTotals& now) {
    if (!running_) return;
    for (size_t e = 0; e < now.size(); ++e) accumulated_[e] += now[e] - snapshot_[e];
    running_ = false;
  }
  uint64_t Read(int event, const EventTotals& now) const {
    if (event < 0 || event >= GAP8_EVT_COUNT || !((mask_ >> event) & 1u)) return 0;
    return accumulated_[event] + (running_ ? now[event] - snapshot_[event] : 0);
  }

 private:
  uint32_t mask_ = 0;
  bool running_ = false;
  EventTotals accumulated_{};
  EventTotals snapshot_{};
};

}  // namespace gap8
