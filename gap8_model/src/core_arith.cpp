// M extension arithmetic, with its costs.
#include "gap8/core.h"
#include "gap8/timing.h"

namespace gap8 {
namespace {

uint32_t Divide(Op op, uint32_t a, uint32_t b) {
  const int32_t sa = static_cast<int32_t>(a), sb = static_cast<int32_t>(b);
  const bool overflow = sa == INT32_MIN && sb == -1;  // RISC-V: quotient = dividend, rem = 0
  switch (op) {
    case Op::kDiv:
      return b == 0 ? ~0u : overflow ? a : static_cast<uint32_t>(sa / sb);
    case Op::kDivu:
      return b == 0 ? ~0u : a / b;
    case Op::kRem:
      return b == 0 ? a : overflow ? 0u : static_cast<uint32_t>(sa % sb);
    default:
      return b == 0 ? a : a % b;
  }
}

}  // namespace

uint32_t Core::ExecuteMulDiv(const Decoded& d) {
  const uint32_t a = regs_[d.rs1], b = regs_[d.rs2];
  const int64_t sa = static_cast<int32_t>(a), sb = static_cast<int32_t>(b);
  uint32_t result, cost;
  switch (d.op) {
    case Op::kMul:
      result = a * b;
      cost = timing::kAlu;
      SetHazardBit(Hazard::kMul, d.rd_bit);
      break;
    case Op::kMulh:
      result = static_cast<uint32_t>(static_cast<uint64_t>(sa * sb) >> 32);
      cost = timing::kMulh;
      break;
    case Op::kMulhsu:
      result = static_cast<uint32_t>(static_cast<uint64_t>(sa * static_cast<int64_t>(b)) >> 32);
      cost = timing::kMulh;
      break;
    case Op::kMulhu:
      result = static_cast<uint32_t>((static_cast<uint64_t>(a) * b) >> 32);
      cost = timing::kMulh;
      break;
    default:
      result = Divide(d.op, a, b);
      cost = timing::Divide(b, d.op == Op::kDiv || d.op == Op::kRem);
      break;
  }
  regs_[d.rd] = result;
  regs_[0] = 0;
  pc_ = NextSequentialPc(pc_ + d.size);
  return cost;
}

}  // namespace gap8
