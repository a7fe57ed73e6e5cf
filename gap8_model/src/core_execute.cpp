// Branches, hardware-loop set-up and the out-of-line Execute; the main switch is in
// core_execute_inline.h.
#include "core_execute_inline.h"

namespace gap8 {

// Hardware-loop rules, in the words of the RI5CY user manual (pulp-platform/riscv
// doc/user_manual.doc, 2018, chapter "PULP Hardware Loop Extensions" and the "Hardware Loops"
// table): "the minimum loop size is two instructions and the last instruction cannot be any
// jump or branch instruction"; "A hardware loop is subject to the following constraints:
// Minimum of 2 instructions in the loop body. Loop counter has to be bigger than 0, since the
// loop body is always entered at least once." The hardware raises no exception for these; the
// model stops the run with a kHardwareLoop fault naming the rule (and, as every fault, the pc).
// Nothing else is checked: that manual documents no alignment rule and does not forbid a
// branch out of the body (CV32E40P's later manual adds such rules; they are not RI5CY's).
[[gnu::cold, gnu::noinline]] void Core::RaiseHwLoop(const char* rule) const {
  Raise(FaultKind::kHardwareLoop, std::string(rule) + " (RI5CY manual, hardware loops)");
}

uint32_t Core::ExecuteBranch(const Decoded& d, bool taken) {
  if (loops_armed_ && AtActiveLoopEnd())
    RaiseHwLoop("the last instruction of a hardware loop must not be a branch");
  ++events_[GAP8_EVT_BRANCH];
  if (!taken) {
    pc_ = NextSequentialPc(pc_ + d.size);
    return timing::kBranchNotTaken;
  }
  ++events_[GAP8_EVT_BTAKEN];
  pc_ += static_cast<uint32_t>(d.imm);
  return timing::kBranchTaken;
}

uint32_t Core::Execute(const Decoded& d) { return ExecuteInline(d); }

uint32_t Core::ExecuteHwLoopSetup(const Decoded& d) {
  const int l = d.loop;
  const uint32_t offset = static_cast<uint32_t>(d.imm) << 1;
  switch (d.op) {
    case Op::kLpStarti:
      loop_start_[l] = pc_ + offset;
      break;
    case Op::kLpEndi:
      loop_end_[l] = pc_ + offset;
      break;
    case Op::kLpCount:
      loop_count_[l] = regs_[d.rs1];
      break;
    case Op::kLpCounti:
      loop_count_[l] = static_cast<uint32_t>(d.imm);
      break;
    case Op::kLpSetup:
      loop_count_[l] = regs_[d.rs1];
      loop_start_[l] = pc_ + 4;
      loop_end_[l] = pc_ + offset;
      break;
    default:  // lp.setupi: count in imm, end offset in the rs1 field
      loop_count_[l] = static_cast<uint32_t>(d.imm);
      loop_start_[l] = pc_ + 4;
      loop_end_[l] = pc_ + (static_cast<uint32_t>(d.rs1) << 1);
      break;
  }
  const bool sets_count = d.op == Op::kLpCount || d.op == Op::kLpCounti || d.op == Op::kLpSetup ||
                          d.op == Op::kLpSetupi;
  if (sets_count && loop_count_[l] == 0) RaiseHwLoop("a hardware loop count must be bigger than 0");
  loops_armed_ = loop_count_[0] != 0 || loop_count_[1] != 0;
  pc_ += d.size;
  return timing::kAlu;
}

}  // namespace gap8
