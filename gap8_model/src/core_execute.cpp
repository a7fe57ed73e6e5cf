// The interpreter's main switch: RV32I, the control flow and the Xpulp arithmetic. Memory,
// M-extension and hardware-loop set-up live in their own functions.
#include "gap8/core.h"
#include "gap8/timing.h"
#include "gap8/xpulp.h"
#include "xpulp_semantics.h"

namespace gap8 {
namespace {

// Operand b of an Xpulp instruction (see Decoded::scalar): rs2, rs2's low lane replicated
// (.sc) or the immediate the decoder prepared (.sci, immediate scalar forms).
uint32_t OperandB(const Decoded& d, uint32_t rs2_value) {
  if (d.scalar == 0) return rs2_value;
  if (d.scalar == 2) return static_cast<uint32_t>(d.imm);
  return d.width ? xpulp::SplatHalf(rs2_value) : xpulp::SplatByte(rs2_value);
}

}  // namespace

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

// True when the instruction at pc is the last one of an active hardware loop.
bool Core::AtActiveLoopEnd() const {
  return (loop_count_[0] != 0 && pc_ == loop_end_[0]) ||
         (loop_count_[1] != 0 && pc_ == loop_end_[1]);
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

// The pc after a non-jumping instruction: a hardware loop's end sends it back to the start.
uint32_t Core::NextSequentialPc(uint32_t next) {
  if (!loops_armed_) return next;
  for (int l = 0; l < 2; ++l) {  // loop 0 is the inner loop: it has priority
    if (loop_count_[l] != 0 && pc_ == loop_end_[l]) {
      if (loop_start_[l] == loop_end_[l])
        RaiseHwLoop("a hardware loop body must have at least 2 instructions");
      if (--loop_count_[l] != 0) return loop_start_[l];
    }
  }
  loops_armed_ = loop_count_[0] != 0 || loop_count_[1] != 0;
  return next;
}

uint32_t Core::Execute(const Decoded& d) {
  current_ = &d;
  ++events_[GAP8_EVT_INSTR];
  events_[GAP8_EVT_RVC] += (d.size == 2);
  SetHazard(Hazard::kAlu, d.rd);
  const uint32_t a = regs_[d.rs1], b = regs_[d.rs2];
  const uint32_t imm = static_cast<uint32_t>(d.imm);
  uint32_t result;
  switch (d.op) {
    case Op::kLui:
      result = imm;
      break;
    case Op::kAuipc:
      result = pc_ + imm;
      break;
    case Op::kAddi:
      result = a + imm;
      break;
    case Op::kSlti:
      result = static_cast<int32_t>(a) < d.imm;
      break;
    case Op::kSltiu:
      result = a < imm;
      break;
    case Op::kXori:
      result = a ^ imm;
      break;
    case Op::kOri:
      result = a | imm;
      break;
    case Op::kAndi:
      result = a & imm;
      break;
    case Op::kSlli:
      result = a << (imm & 31);
      break;
    case Op::kSrli:
      result = a >> (imm & 31);
      break;
    case Op::kSrai:
      result = static_cast<uint32_t>(static_cast<int32_t>(a) >> (imm & 31));
      break;
    case Op::kAdd:
      result = a + b;
      break;
    case Op::kSub:
      result = a - b;
      break;
    case Op::kSll:
      result = a << (b & 31);
      break;
    case Op::kSlt:
      result = static_cast<int32_t>(a) < static_cast<int32_t>(b);
      break;
    case Op::kSltu:
      result = a < b;
      break;
    case Op::kXor:
      result = a ^ b;
      break;
    case Op::kSrl:
      result = a >> (b & 31);
      break;
    case Op::kSra:
      result = static_cast<uint32_t>(static_cast<int32_t>(a) >> (b & 31));
      break;
    case Op::kOr:
      result = a | b;
      break;
    case Op::kAnd:
      result = a & b;
      break;
    case Op::kCsrRead:
      result = static_cast<uint32_t>(id_);
      break;  // mhartid: cluster 0
    case Op::kFence:
      result = 0;
      break;
    case Op::kJal:
    case Op::kJalr: {
      if (loops_armed_ && AtActiveLoopEnd())
        RaiseHwLoop("the last instruction of a hardware loop must not be a jump");
      ++events_[GAP8_EVT_JUMP];
      const uint32_t target = d.op == Op::kJal ? pc_ + imm : (a + imm) & ~1u;
      regs_[d.rd] = pc_ + d.size;
      regs_[0] = 0;
      pc_ = target;
      return timing::kJump;
    }
    case Op::kBeq:
      return ExecuteBranch(d, a == b);
    case Op::kBne:
      return ExecuteBranch(d, a != b);
    case Op::kBlt:
      return ExecuteBranch(d, static_cast<int32_t>(a) < static_cast<int32_t>(b));
    case Op::kBge:
      return ExecuteBranch(d, static_cast<int32_t>(a) >= static_cast<int32_t>(b));
    case Op::kBltu:
      return ExecuteBranch(d, a < b);
    case Op::kBgeu:
      return ExecuteBranch(d, a >= b);
    case Op::kLoad:
    case Op::kStore:
      return ExecuteMemory(d);
    case Op::kMul:
    case Op::kMulh:
    case Op::kMulhsu:
    case Op::kMulhu:
    case Op::kDiv:
    case Op::kDivu:
    case Op::kRem:
    case Op::kRemu:
      return ExecuteMulDiv(d);
      // Xpulp: one generated case per op of gap8_model/isa/xpulp.tbl, by its class and path.
#include "gap8/xpulp_execute.inc"
    default:  // kIllegal, kUndecoded
      Raise(FaultKind::kIllegalInstruction, "illegal instruction");
  }
  regs_[d.rd] = result;
  regs_[0] = 0;
  pc_ = NextSequentialPc(pc_ + d.size);
  return timing::kAlu;
}

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
