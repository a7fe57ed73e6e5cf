// PULPv2 packed-SIMD (opcode 1010111) and hardware-loop (opcode 1111011) decoding. Encodings
// follow the PULPv2 instruction tables of GreenWaves' GVSOC ISS (isa_riscv_gen.py, pulp_v2).
#include "decode_fields.h"
#include "gap8/decoded.h"

namespace gap8 {
namespace {

Decoded Illegal(uint32_t w) {
  Decoded d;
  d.op = Op::kIllegal;
  d.raw = w;
  return d;
}

// funct6 (bits 31:26) of the byte-wise operations the model implements.
Op SimdOp(uint32_t funct6) {
  switch (funct6) {
    case 0x00:
      return Op::kPvAddB;
    case 0x02:
      return Op::kPvSubB;
    case 0x06:
      return Op::kPvAvguB;
    case 0x0A:
      return Op::kPvMinuB;
    case 0x0E:
      return Op::kPvMaxuB;
    case 0x1C:
      return Op::kPvAbsB;
    case 0x20:
      return Op::kPvDotupB;
    case 0x22:
      return Op::kPvDotuspB;
    case 0x28:
      return Op::kPvSdotupB;
    case 0x2A:
      return Op::kPvSdotuspB;
    default:
      return Op::kIllegal;
  }
}

}  // namespace

Decoded DecodeXpulpSimd(uint32_t w) {
  const uint32_t f3 = Bits(w, 14, 12);
  // funct3 001 is the vector-vector byte form, 101 the vector-scalar (.sc) byte form; the
  // halfword and immediate (.sci) forms are not modelled.
  if (f3 != 1 && f3 != 5) return Illegal(w);
  const Op op = SimdOp(Bits(w, 31, 26));
  if (op == Op::kIllegal) return Illegal(w);
  if (op == Op::kPvAbsB && (f3 != 1 || Bits(w, 25, 25) != 0)) return Illegal(w);
  Decoded d = Base(w, op);
  d.scalar = (f3 == 5);
  if (op == Op::kPvAbsB) d.src_mask = RegBit(d.rs1);
  if (op == Op::kPvSdotupB || op == Op::kPvSdotuspB) d.src_mask |= RegBit(d.rd);  // accumulator
  return d;
}

Decoded DecodeHwLoop(uint32_t w) {
  if (Bits(w, 11, 8) != 0) return Illegal(w);
  static constexpr Op kOps[8] = {Op::kLpStarti, Op::kLpEndi,   Op::kLpCount, Op::kLpCounti,
                                 Op::kLpSetup,  Op::kLpSetupi, Op::kIllegal, Op::kIllegal};
  const uint32_t f3 = Bits(w, 14, 12);
  if (kOps[f3] == Op::kIllegal) return Illegal(w);
  Decoded d = Base(w, kOps[f3]);
  d.loop = Bits(w, 7, 7);
  d.rd = 0;
  d.rs2 = 0;
  d.imm = static_cast<int32_t>(Bits(w, 31, 20));  // unsigned: offsets in half-words, or a count
  const bool reads_rs1 = (kOps[f3] == Op::kLpCount || kOps[f3] == Op::kLpSetup);
  d.src_mask = reads_rs1 ? RegBit(d.rs1) : 0;
  return d;
}

}  // namespace gap8
