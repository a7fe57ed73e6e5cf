// Fetch, hazards, faults, wake-up and event totals of a core.
#include "gap8/core.h"
#include "gap8/timing.h"

namespace gap8 {

void Core::RaiseFetchFault() const {
  throw Fault{FaultKind::kMemory, id_, pc_, 0,
              "instruction fetch from unmapped address " + Hex(pc_)};
}

// The next instruction stalls on the pending result: count the stall and consume the hazard.
void Core::ConsumeHazardStall() {
  if (hazard_ == Hazard::kLoad) ++events_[GAP8_EVT_LD_STALL];
  if (hazard_ == Hazard::kAlu) ++events_[GAP8_EVT_JR_STALL];
  ClearHazard();
}

void Core::Raise(FaultKind kind, const std::string& what) const {
  throw Fault{kind, id_, pc_, current_ ? current_->raw : 0u, what};
}

void Core::Wake(uint64_t at, uint32_t value) {
  const uint64_t resume = at + timing::kWakeUp;
  if (resume > time) {
    slept += resume - time;
    time = resume;
  }
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
