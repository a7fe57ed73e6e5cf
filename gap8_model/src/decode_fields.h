// Bit-field helpers shared by the 32-bit and compressed decoders.
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
