// The interpreter's main switch: RV32I, the control flow and the Xpulp arithmetic, inline so
// that the cluster's issue loops run it without a call (Core::Execute is the same, out of line).
// Memory, M-extension, branches and hardware-loop set-up live in their own functions.
#pragma once

#include "gap8/core.h"
#include "gap8/timing.h"
#include "gap8/xpulp.h"
#include "xpulp_semantics.h"

namespace gap8 {
namespace execute_detail {

// Operand b of an Xpulp instruction (see Decoded::scalar): rs2, rs2's low lane replicated
// (.sc) or the immediate the decoder prepared (.sci, immediate scalar forms).
inline uint32_t OperandB(const Decoded& d, uint32_t rs2_value) {
  if (d.scalar == 0) return rs2_value;
  if (d.scalar == 2) return static_cast<uint32_t>(d.imm);
  return d.width ? xpulp::SplatHalf(rs2_value) : xpulp::SplatByte(rs2_value);
}

}  // namespace execute_detail

[[gnu::always_inline]] inline uint32_t Core::ExecuteInline(const Decoded& d) {
  using execute_detail::OperandB;
  current_ = &d;
  ++events_[GAP8_EVT_INSTR];
  events_[GAP8_EVT_RVC] += d.rvc;
  SetHazardBit(Hazard::kAlu, d.rd_bit);
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

}  // namespace gap8
