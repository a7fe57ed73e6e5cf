// Bit-field helpers shared by the decoders and the disassembler.
#pragma once

#include <cstdint>

#include "gap8/decoded.h"

namespace gap8 {

// Bits hi..lo of x, right-aligned.
constexpr uint32_t Bits(uint32_t x, int hi, int lo) {
  return (x >> lo) & ((hi - lo == 31) ? 0xFFFFFFFFu : ((1u << (hi - lo + 1)) - 1u));
}

// Sign-extends the low `width` bits of x.
constexpr int32_t SignExtend(uint32_t x, int width) {
  const uint32_t m = 1u << (width - 1);
  x &= (width == 32) ? 0xFFFFFFFFu : ((1u << width) - 1u);
  return static_cast<int32_t>((x ^ m) - m);
}

// The RV32I immediates (I, S, B formats), also used by the Xpulp loads, stores and branches.
constexpr int32_t ImmI(uint32_t w) { return SignExtend(Bits(w, 31, 20), 12); }
constexpr int32_t ImmS(uint32_t w) {
  return SignExtend((Bits(w, 31, 25) << 5) | Bits(w, 11, 7), 12);
}
constexpr int32_t ImmB(uint32_t w) {
  return SignExtend((Bits(w, 31, 31) << 12) | (Bits(w, 7, 7) << 11) | (Bits(w, 30, 25) << 5) |
                        (Bits(w, 11, 8) << 1),
                    13);
}

inline uint32_t RegBit(uint32_t reg) { return reg == 0 ? 0u : (1u << reg); }

// The register fields of the instruction tables' operand formats (isa/isa_format.py's FIELDS,
// in its order): rd 11..7, rs1 19..15, rs2 24..20, RVC's rs2 6..2, rs2' and rs1' (x8 + 4..2,
// x8 + 9..7), and the fixed sp and ra. kNoField: none (register x0).
enum Field : uint8_t { kRd, kRs1, kRs2, kCRs2, kCRs2p, kCRs1p, kSp, kRa, kFields, kNoField };

constexpr uint32_t FieldRegister(Field f, uint32_t w) {
  switch (f) {
    case kRd:
      return Bits(w, 11, 7);
    case kRs1:
      return Bits(w, 19, 15);
    case kRs2:
      return Bits(w, 24, 20);
    case kCRs2:
      return Bits(w, 6, 2);
    case kCRs2p:
      return 8 + Bits(w, 4, 2);
    case kCRs1p:
      return 8 + Bits(w, 9, 7);
    case kSp:
      return 2;
    case kRa:
      return 1;
    default:
      return 0;
  }
}

// Bit r for each register r != x0 of the fields (bit f: Field f) of w.
inline uint32_t FieldsMask(uint32_t fields, uint32_t w) {
  uint32_t mask = 0;
  for (int f = 0; f < kFields; ++f)
    if (fields & (1u << f)) mask |= RegBit(FieldRegister(static_cast<Field>(f), w));
  return mask;
}

// The RV32IMC immediates of rv32imc.tbl's operand tokens (isa/gen_rv32imc.py's IMMEDIATES):
// the RV32I formats and the RVC ones (the RISC-V spec's RVC immediate layouts).
enum class RvImm : uint8_t {
  kNone,
  kU20,     // u20: lui, auipc (the upper 20 bits in place)
  kJ,       // jt: jal's offset
  kB,       // bt: a branch's offset
  kI,       // i12
  kS,       // s12
  kShamt,   // shamt: bits 24..20
  kCi6,     // ci6: c.addi, c.li, c.andi (signed)
  kCShamt,  // cshamt: c.slli, c.srli, c.srai
  kCLui,    // clui: c.lui's upper immediate, in place
  kC16sp,   // c16sp
  kC4spn,   // c4spn
  kClw,     // clw: c.lw / c.sw offset
  kClwsp,   // clwsp
  kCswsp,   // cswsp
  kCj,      // cj: c.j / c.jal offset
  kCb,      // cb: c.beqz / c.bnez offset
};

constexpr int32_t CImm6(uint32_t h) {
  return SignExtend((Bits(h, 12, 12) << 5) | Bits(h, 6, 2), 6);
}

constexpr int32_t RvImmediate(RvImm kind, uint32_t w) {
  switch (kind) {
    case RvImm::kNone:
      return 0;
    case RvImm::kU20:
      return static_cast<int32_t>(w & 0xFFFFF000u);
    case RvImm::kJ:
      return SignExtend((Bits(w, 31, 31) << 20) | (Bits(w, 19, 12) << 12) |
                            (Bits(w, 20, 20) << 11) | (Bits(w, 30, 21) << 1),
                        21);
    case RvImm::kB:
      return ImmB(w);
    case RvImm::kI:
      return ImmI(w);
    case RvImm::kS:
      return ImmS(w);
    case RvImm::kShamt:
      return static_cast<int32_t>(Bits(w, 24, 20));
    case RvImm::kCi6:
      return CImm6(w);
    case RvImm::kCShamt:
      return static_cast<int32_t>((Bits(w, 12, 12) << 5) | Bits(w, 6, 2));
    case RvImm::kCLui:
      return static_cast<int32_t>(static_cast<uint32_t>(CImm6(w)) << 12);
    case RvImm::kC16sp:
      return SignExtend((Bits(w, 12, 12) << 9) | (Bits(w, 6, 6) << 4) | (Bits(w, 5, 5) << 6) |
                            (Bits(w, 4, 3) << 7) | (Bits(w, 2, 2) << 5),
                        10);
    case RvImm::kC4spn:
      return static_cast<int32_t>((Bits(w, 12, 11) << 4) | (Bits(w, 10, 7) << 6) |
                                  (Bits(w, 6, 6) << 2) | (Bits(w, 5, 5) << 3));
    case RvImm::kClw:
      return static_cast<int32_t>((Bits(w, 12, 10) << 3) | (Bits(w, 6, 6) << 2) |
                                  (Bits(w, 5, 5) << 6));
    case RvImm::kClwsp:
      return static_cast<int32_t>((Bits(w, 12, 12) << 5) | (Bits(w, 6, 4) << 2) |
                                  (Bits(w, 3, 2) << 6));
    case RvImm::kCswsp:
      return static_cast<int32_t>((Bits(w, 12, 9) << 2) | (Bits(w, 8, 7) << 6));
    case RvImm::kCj:
      return SignExtend((Bits(w, 12, 12) << 11) | (Bits(w, 11, 11) << 4) | (Bits(w, 10, 9) << 8) |
                            (Bits(w, 8, 8) << 10) | (Bits(w, 7, 7) << 6) | (Bits(w, 6, 6) << 7) |
                            (Bits(w, 5, 3) << 1) | (Bits(w, 2, 2) << 5),
                        12);
    case RvImm::kCb:
      return SignExtend((Bits(w, 12, 12) << 8) | (Bits(w, 11, 10) << 3) | (Bits(w, 6, 5) << 6) |
                            (Bits(w, 4, 3) << 1) | (Bits(w, 2, 2) << 5),
                        9);
  }
  return 0;
}

// Fills the register fields every 32-bit format shares and the default source mask (rs1, rs2).
inline Decoded Base(uint32_t w, Op op) {
  Decoded d;
  d.op = op;
  d.raw = w;
  d.rd = Bits(w, 11, 7);
  d.rs1 = Bits(w, 19, 15);
  d.rs2 = Bits(w, 24, 20);
  d.src_mask = RegBit(d.rs1) | RegBit(d.rs2);
  return d;
}

// The Xpulp instructions of gap8_model/isa/xpulp.tbl; Illegal for any other word.
Decoded DecodeXpulp(uint32_t w);

}  // namespace gap8
