// RV32C decoder (RISC-V unprivileged spec, chapter "C" standard extension). Floating-point and
// RV64-only encodings are illegal here: the cluster cores have no FPU.
#include "decode_compressed.h"

#include "decode_fields.h"

namespace gap8 {
namespace {

Decoded Make(uint32_t half, Op op, uint32_t rd, uint32_t rs1, uint32_t rs2, int32_t imm) {
  Decoded d;
  d.op = op;
  d.raw = half;
  d.size = 2;
  d.rd = rd;
  d.rs1 = rs1;
  d.rs2 = rs2;
  d.imm = imm;
  d.src_mask = RegBit(rs1) | RegBit(rs2);
  return d;
}

Decoded Illegal(uint32_t half) {
  Decoded d;
  d.op = Op::kIllegal;
  d.raw = half;
  d.size = 2;
  return d;
}

uint32_t RegPrime(uint32_t h, int lo) { return 8 + Bits(h, lo + 2, lo); }
int32_t Imm6(uint32_t h) { return SignExtend((Bits(h, 12, 12) << 5) | Bits(h, 6, 2), 6); }

int32_t JumpOffset(uint32_t h) {
  uint32_t v = (Bits(h, 12, 12) << 11) | (Bits(h, 11, 11) << 4) | (Bits(h, 10, 9) << 8) |
               (Bits(h, 8, 8) << 10) | (Bits(h, 7, 7) << 6) | (Bits(h, 6, 6) << 7) |
               (Bits(h, 5, 3) << 1) | (Bits(h, 2, 2) << 5);
  return SignExtend(v, 12);
}

int32_t BranchOffset(uint32_t h) {
  uint32_t v = (Bits(h, 12, 12) << 8) | (Bits(h, 11, 10) << 3) | (Bits(h, 6, 5) << 6) |
               (Bits(h, 4, 3) << 1) | (Bits(h, 2, 2) << 5);
  return SignExtend(v, 9);
}

Decoded Width(Decoded d, uint8_t width) {
  d.width = width;
  return d;
}

Decoded Quadrant0(uint32_t h) {
  const uint32_t rs1 = RegPrime(h, 7), r2 = RegPrime(h, 2);
  const int32_t mem_off =
      static_cast<int32_t>((Bits(h, 12, 10) << 3) | (Bits(h, 6, 6) << 2) | (Bits(h, 5, 5) << 6));
  switch (Bits(h, 15, 13)) {
    case 0: {  // c.addi4spn
      uint32_t imm = (Bits(h, 12, 11) << 4) | (Bits(h, 10, 7) << 6) | (Bits(h, 6, 6) << 2) |
                     (Bits(h, 5, 5) << 3);
      if (imm == 0) return Illegal(h);
      return Make(h, Op::kAddi, r2, 2, 0, static_cast<int32_t>(imm));
    }
    case 2:
      return Width(Make(h, Op::kLoad, r2, rs1, 0, mem_off), 2);  // c.lw
    case 6:
      return Width(Make(h, Op::kStore, 0, rs1, r2, mem_off), 2);  // c.sw
    default:
      return Illegal(h);
  }
}

Decoded ArithmeticQ1(uint32_t h) {
  const uint32_t rd = RegPrime(h, 7), rs2 = RegPrime(h, 2);
  switch (Bits(h, 11, 10)) {
    case 0:
    case 1: {  // c.srli / c.srai; shamt[5] = 1 is reserved on RV32
      if (Bits(h, 12, 12)) return Illegal(h);
      Op op = Bits(h, 11, 10) == 0 ? Op::kSrli : Op::kSrai;
      return Make(h, op, rd, rd, 0, static_cast<int32_t>(Bits(h, 6, 2)));
    }
    case 2:
      return Make(h, Op::kAndi, rd, rd, 0, Imm6(h));
    default: {
      if (Bits(h, 12, 12)) return Illegal(h);  // c.subw / c.addw are RV64 only
      static constexpr Op kOps[4] = {Op::kSub, Op::kXor, Op::kOr, Op::kAnd};
      return Make(h, kOps[Bits(h, 6, 5)], rd, rd, rs2, 0);
    }
  }
}

Decoded Quadrant1(uint32_t h) {
  const uint32_t rd = Bits(h, 11, 7);
  switch (Bits(h, 15, 13)) {
    case 0:
      return Make(h, Op::kAddi, rd, rd, 0, Imm6(h));  // c.addi, c.nop
    case 1:
      return Make(h, Op::kJal, 1, 0, 0, JumpOffset(h));  // c.jal
    case 2:
      return Make(h, Op::kAddi, rd, 0, 0, Imm6(h));  // c.li
    case 3: {
      if (Imm6(h) == 0) return Illegal(h);
      if (rd == 2) {  // c.addi16sp
        uint32_t v = (Bits(h, 12, 12) << 9) | (Bits(h, 6, 6) << 4) | (Bits(h, 5, 5) << 6) |
                     (Bits(h, 4, 3) << 7) | (Bits(h, 2, 2) << 5);
        return Make(h, Op::kAddi, 2, 2, 0, SignExtend(v, 10));
      }
      return Make(h, Op::kLui, rd, 0, 0,
                  static_cast<int32_t>(static_cast<uint32_t>(Imm6(h)) << 12));
    }
    case 4:
      return ArithmeticQ1(h);
    case 5:
      return Make(h, Op::kJal, 0, 0, 0, JumpOffset(h));  // c.j
    case 6:
      return Make(h, Op::kBeq, 0, RegPrime(h, 7), 0, BranchOffset(h));
    default:
      return Make(h, Op::kBne, 0, RegPrime(h, 7), 0, BranchOffset(h));
  }
}

Decoded JumpOrMove(uint32_t h) {
  const uint32_t rd = Bits(h, 11, 7), rs2 = Bits(h, 6, 2);
  if (Bits(h, 12, 12) == 0) {
    if (rs2 != 0) return Make(h, Op::kAdd, rd, 0, rs2, 0);  // c.mv
    if (rd == 0) return Illegal(h);
    return Make(h, Op::kJalr, 0, rd, 0, 0);  // c.jr
  }
  if (rs2 != 0) return Make(h, Op::kAdd, rd, rd, rs2, 0);  // c.add
  if (rd == 0) return Illegal(h);                          // c.ebreak: no debugger modelled
  return Make(h, Op::kJalr, 1, rd, 0, 0);                  // c.jalr
}

Decoded Quadrant2(uint32_t h) {
  const uint32_t rd = Bits(h, 11, 7);
  switch (Bits(h, 15, 13)) {
    case 0:  // c.slli
      if (Bits(h, 12, 12)) return Illegal(h);
      return Make(h, Op::kSlli, rd, rd, 0, static_cast<int32_t>(Bits(h, 6, 2)));
    case 2: {  // c.lwsp
      if (rd == 0) return Illegal(h);
      uint32_t off = (Bits(h, 12, 12) << 5) | (Bits(h, 6, 4) << 2) | (Bits(h, 3, 2) << 6);
      return Width(Make(h, Op::kLoad, rd, 2, 0, static_cast<int32_t>(off)), 2);
    }
    case 4:
      return JumpOrMove(h);
    case 6: {  // c.swsp
      uint32_t off = (Bits(h, 12, 9) << 2) | (Bits(h, 8, 7) << 6);
      return Width(Make(h, Op::kStore, 0, 2, Bits(h, 6, 2), static_cast<int32_t>(off)), 2);
    }
    default:
      return Illegal(h);
  }
}

}  // namespace

Decoded DecodeCompressed(uint32_t half) {
  switch (half & 3u) {
    case 0:
      return half == 0 ? Illegal(half) : Quadrant0(half);
    case 1:
      return Quadrant1(half);
    default:
      return Quadrant2(half);
  }
}

}  // namespace gap8
