// The interpreter's main switch: RV32I, the control flow and the Xpulp arithmetic. Memory,
// M-extension and hardware-loop set-up live in their own functions.
#include "gap8/core.h"
#include "gap8/timing.h"
#include "gap8/xpulp.h"

namespace gap8 {
namespace {

// pv.*.sc.b: operand b is rs2's low byte in every lane.
uint32_t SimdOperandB(const Decoded& d, uint32_t rs2_value) {
  const uint32_t scalar_mask = 0u - (d.scalar != 0);  // a select, not a branch
  return (xpulp::SplatByte(rs2_value) & scalar_mask) | (rs2_value & ~scalar_mask);
}

}  // namespace

uint32_t Core::ExecuteBranch(const Decoded& d, bool taken) {
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
    case Op::kLoadPostImm:
    case Op::kLoadRegReg:
    case Op::kLoadPostReg:
    case Op::kStorePostImm:
    case Op::kStoreRegReg:
    case Op::kStorePostReg:
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
    case Op::kLpStarti:
    case Op::kLpEndi:
    case Op::kLpCount:
    case Op::kLpCounti:
    case Op::kLpSetup:
    case Op::kLpSetupi:
      return ExecuteHwLoopSetup(d);
    // Xpulp arithmetic sits in this switch too: one dispatch per instruction, not two.
    case Op::kPAbs:
      result = xpulp::Abs(a);
      break;
    case Op::kPMin:
      result = xpulp::Min(a, b);
      break;
    case Op::kPMinu:
      result = xpulp::Minu(a, b);
      break;
    case Op::kPMax:
      result = xpulp::Max(a, b);
      break;
    case Op::kPMaxu:
      result = xpulp::Maxu(a, b);
      break;
    case Op::kPvAddB:
      result = xpulp::AddB(a, SimdOperandB(d, b));
      break;
    case Op::kPvSubB:
      result = xpulp::SubB(a, SimdOperandB(d, b));
      break;
    case Op::kPvAvguB:
      result = xpulp::AvguB(a, SimdOperandB(d, b));
      break;
    case Op::kPvMinuB:
      result = xpulp::MinuB(a, SimdOperandB(d, b));
      break;
    case Op::kPvMaxuB:
      result = xpulp::MaxuB(a, SimdOperandB(d, b));
      break;
    case Op::kPvAbsB:
      result = xpulp::AbsB(a);
      break;
    case Op::kPvDotupB:
      result = xpulp::DotupB(a, SimdOperandB(d, b));
      break;
    case Op::kPvDotuspB:
      result = xpulp::DotuspB(a, SimdOperandB(d, b));
      break;
    case Op::kPvSdotupB:
      result = xpulp::SdotupB(regs_[d.rd], a, SimdOperandB(d, b));
      break;
    case Op::kPvSdotuspB:
      result = xpulp::SdotuspB(regs_[d.rd], a, SimdOperandB(d, b));
      break;
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
  loops_armed_ = loop_count_[0] != 0 || loop_count_[1] != 0;
  pc_ += d.size;
  return timing::kAlu;
}

}  // namespace gap8
