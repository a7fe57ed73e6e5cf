// Fetch, hazards, faults, wake-up and event totals of a core.
#include <algorithm>

#include "gap8/core.h"
#include "gap8/timing.h"

namespace gap8 {

void Core::RaiseFetchFault() const {
  throw Fault{FaultKind::kMemory,
              id_,
              pc_,
              0,
              "instruction fetch from unmapped address " + Hex(pc_),
              false};
}

// The next instruction stalls on the pending result: count the stall, consume the hazard and
// return its cycles.
uint32_t Core::ConsumeHazardStall() {
  uint32_t cycles = timing::kMulUseStall;
  if (hazard_ == Hazard::kLoad) {
    ++events_[GAP8_EVT_LD_STALL];
    cycles = timing::kLoadUseStall;
  }
  if (hazard_ == Hazard::kAlu) {
    ++events_[GAP8_EVT_JR_STALL];
    cycles = timing::kJumpRegStall;
  }
  ClearHazard();
  return cycles;
}

void Core::Raise(FaultKind kind, const std::string& what) const {
  throw Fault{kind, id_, pc_, current_ ? current_->raw : 0u, what};
}

// Asleep until the event at `at` (clock-gated: not active), then the event unit's answer and
// the core's restart (timing.h kWakeUp), which GVSOC counts as active cycles.
void Core::Wake(uint64_t at, uint32_t value) {
  if (at > time) {
    slept += at - time;
    time = at;
  }
  time = std::max(time, at + timing::kWakeUp);
  if (wake_rd != 0) regs_[wake_rd] = value;
  asleep = false;
  wake_rd = 0;
}

EventTotals Core::Totals() const {
  EventTotals t{};
  for (int e = 0; e < GAP8_EVT_COUNT; ++e) t[e] = events_[e];
  t[GAP8_EVT_CYCLES] = time;
  t[GAP8_EVT_ACTIVE_CYCLES] = time - slept;
  return t;
}

}  // namespace gap8
