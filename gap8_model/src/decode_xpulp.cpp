// Xpulp decoding: the first row of gap8_model/isa/xpulp.tbl whose mask and match fit the word
// (the generator refuses overlapping rows, so the first is the only one). A row gives the op,
// the registers read (the hazard mask), the immediate's kind, the width and operand b's form;
// this file only knows how to cut each immediate kind out of the word.
#include "decode_fields.h"
#include "gap8/decoded.h"
#include "gap8/xpulp.h"

namespace gap8 {
namespace {

enum class XpulpImm : uint8_t {
  kNone,
  kConst,   // the row's constant
  kSimm6,   // the .sci immediate, sign-extended, replicated in every lane
  kUimm6,   // the .sci immediate, zero-extended, replicated
  kLane6,   // the .sci immediate as it is: pv.extract / pv.insert's lane index
  kShufH,   // pv.shuffle.sci.h: the selector bits I1, I0 in the two lanes
  kShufI0,  // pv.shuffleI{k}.sci.b: the selector of the equivalent pv.shuffle.b
  kShufI1,
  kShufI2,
  kShufI3,
  kIs2,       // bits 24..20
  kBitfield,  // (Is3 << 5) | Is2, bits 29..25 and 24..20
  kIs3,       // bits 29..25
  kI12,
  kS12,
  kB13,
  kHwLoop,  // bits 31..20 unsigned (offset in half-words, or a count); loop number bit 7
};

enum : uint8_t { kReadsRs1 = 1, kReadsRs2 = 2, kReadsRd = 4 };

struct XpulpRow {
  uint32_t match, mask;
  Op op;
  uint8_t reads;  // kReads* bits
  bool writes_rd;
  XpulpImm imm;
  int8_t imm_const;
  uint8_t width;
  uint8_t scalar;  // Decoded::scalar: operand b is rs2 (0), rs2's lane replicated (1), imm (2)
};

constexpr XpulpRow kRows[] = {
#include "gap8/xpulp_decode.inc"
};

Decoded Illegal(uint32_t w) {
  Decoded d;
  d.op = Op::kIllegal;
  d.raw = w;
  return d;
}

// The 6-bit immediate of the .sci forms: imm[0] = bit 25, imm[5:1] = bits 24..20 [GVSOC
// Ranges([[25, 1, 0], [20, 5, 1]])].
uint32_t SimdImm6(uint32_t w) { return (Bits(w, 24, 20) << 1) | Bits(w, 25, 25); }

uint32_t Splat(uint32_t value, bool half) {
  return half ? xpulp::SplatHalf(value) : xpulp::SplatByte(value);
}

// pv.shuffleI{k}.sci.b: the result's top byte is byte k of rs1, the others bytes I[5:4],
// I[3:2], I[1:0] [RI5CY; GVSOC lib_VEC_SHUFFLEI*_SCI_8]: pv.shuffle.b with that selector.
uint32_t ShuffleISelector(uint32_t imm6, uint32_t k) {
  return (k << 24) | (((imm6 >> 4) & 3) << 16) | (((imm6 >> 2) & 3) << 8) | (imm6 & 3);
}

int32_t Immediate(const XpulpRow& r, uint32_t w) {
  const uint32_t imm6 = SimdImm6(w);
  const bool half = r.width == 1;
  switch (r.imm) {
    case XpulpImm::kNone:
      return 0;
    case XpulpImm::kConst:
      return r.imm_const;
    case XpulpImm::kSimm6:
      return static_cast<int32_t>(Splat(static_cast<uint32_t>(SignExtend(imm6, 6)), half));
    case XpulpImm::kUimm6:
      return static_cast<int32_t>(Splat(imm6, half));
    case XpulpImm::kLane6:
      return static_cast<int32_t>(imm6);
    case XpulpImm::kShufH:
      return static_cast<int32_t>((((imm6 >> 1) & 1) << 16) | (imm6 & 1));
    case XpulpImm::kShufI0:
    case XpulpImm::kShufI1:
    case XpulpImm::kShufI2:
    case XpulpImm::kShufI3: {
      const auto k = static_cast<uint32_t>(r.imm) - static_cast<uint32_t>(XpulpImm::kShufI0);
      return static_cast<int32_t>(ShuffleISelector(imm6, k));
    }
    case XpulpImm::kIs2:
      return static_cast<int32_t>(Bits(w, 24, 20));
    case XpulpImm::kBitfield:
      return static_cast<int32_t>((Bits(w, 29, 25) << 5) | Bits(w, 24, 20));
    case XpulpImm::kIs3:
      return static_cast<int32_t>(Bits(w, 29, 25));
    case XpulpImm::kI12:
      return ImmI(w);
    case XpulpImm::kS12:
      return ImmS(w);
    case XpulpImm::kB13:
      return ImmB(w);
    case XpulpImm::kHwLoop:
      return static_cast<int32_t>(Bits(w, 31, 20));
  }
  return 0;
}

Decoded FromRow(const XpulpRow& r, uint32_t w) {
  Decoded d = Base(w, r.op);
  d.src_mask = ((r.reads & kReadsRs1) ? RegBit(d.rs1) : 0u) |
               ((r.reads & kReadsRs2) ? RegBit(d.rs2) : 0u) |
               ((r.reads & kReadsRd) ? RegBit(d.rd) : 0u);
  d.imm = Immediate(r, w);
  d.width = r.width;
  d.scalar = r.scalar;
  if (!r.writes_rd && (r.reads & kReadsRd) == 0) d.rd = 0;  // the rd field holds an immediate
  if (r.imm == XpulpImm::kHwLoop) {
    d.loop = static_cast<uint8_t>(Bits(w, 7, 7));
    d.rs2 = 0;  // the rs2 field belongs to the count or offset
  }
  return d;
}

}  // namespace

Decoded DecodeXpulp(uint32_t w) {
  for (const XpulpRow& r : kRows)
    if ((w & r.mask) == r.match) return FromRow(r, w);
  return Illegal(w);
}

}  // namespace gap8
