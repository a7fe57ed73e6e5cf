// PULPv2 (Xpulp) decoding: packed SIMD (opcode 1010111), the extra ALU operations on OP
// (0110011), the 16-bit multiply-accumulate and normalised add/sub (1011011), the
// immediate branches and the hardware loops (1111011). Encodings: GVSOC's PULPv2 table
// (gvsoc-core models/cpu/iss/isa_gen/isa_pulpv2.py, the subset GVSOC's GAP8 core runs), which
// matches the "Xgap8" entries of GreenWaves' binutils (riscv-opc.c) and the RI5CY manual's
// encoding tables. Anything else in these opcodes is an illegal instruction.
#include "decode_fields.h"
#include "gap8/decoded.h"
#include "gap8/xpulp.h"

namespace gap8 {
namespace {

Decoded Illegal(uint32_t w) {
  Decoded d;
  d.op = Op::kIllegal;
  d.raw = w;
  return d;
}

// funct3 of opcode 1010111: lane width and where operand b comes from.
constexpr uint8_t kFormH = 1u << 0, kFormB = 1u << 1, kFormScH = 1u << 4, kFormScB = 1u << 5,
                  kFormSciH = 1u << 6, kFormSciB = 1u << 7;
constexpr uint8_t kAllForms = kFormH | kFormB | kFormScH | kFormScB | kFormSciH | kFormSciB;

struct SimdEntry {
  Op b = Op::kIllegal, h = Op::kIllegal;
  uint8_t forms = 0;        // the funct3 values that exist for this funct6
  bool sci_signed = false;  // .sci immediate sign-extended (else zero-extended)
  bool reads_rd = false;    // accumulating or merging into rd
};

// Indexed by funct6 (bits 31..26) [GVSOC isa_pulpv2.py]. The .sci signedness is GVSOC's
// format per instruction (RRS signed, RRU unsigned), which matches the RI5CY manual's notes
// ("Immediate is zero-extended" for minu, maxu, srl, sra, sll; sign-extended otherwise; for sra
// the two readings agree since only the low 3 or 4 bits of the shift are used).
constexpr SimdEntry SimdTable(uint32_t funct6) {
  switch (funct6) {
    case 0x00:
      return {Op::kPvAddB, Op::kPvAddH, kAllForms, true};
    case 0x02:
      return {Op::kPvSubB, Op::kPvSubH, kAllForms, true};
    case 0x04:
      return {Op::kPvAvgB, Op::kPvAvgH, kAllForms, true};
    case 0x06:
      return {Op::kPvAvguB, Op::kPvAvguH, kAllForms, false};
    case 0x08:
      return {Op::kPvMinB, Op::kPvMinH, kAllForms, true};
    case 0x0A:
      return {Op::kPvMinuB, Op::kPvMinuH, kAllForms, false};
    case 0x0C:
      return {Op::kPvMaxB, Op::kPvMaxH, kAllForms, true};
    case 0x0E:
      return {Op::kPvMaxuB, Op::kPvMaxuH, kAllForms, false};
    case 0x10:
      return {Op::kPvSrlB, Op::kPvSrlH, kAllForms, false};
    case 0x12:
      return {Op::kPvSraB, Op::kPvSraH, kAllForms, true};
    case 0x14:
      return {Op::kPvSllB, Op::kPvSllH, kAllForms, false};
    case 0x16:
      return {Op::kPvOr, Op::kPvOr, kAllForms, true};
    case 0x18:
      return {Op::kPvXor, Op::kPvXor, kAllForms, true};
    case 0x1A:
      return {Op::kPvAnd, Op::kPvAnd, kAllForms, true};
    case 0x1C:
      return {Op::kPvAbsB, Op::kPvAbsH, kFormH | kFormB};
    case 0x1E:
      return {Op::kPvExtractB, Op::kPvExtractH, kFormSciH | kFormSciB, false};
    case 0x24:
      return {Op::kPvExtractuB, Op::kPvExtractuH, kFormSciH | kFormSciB, false};
    case 0x2C:
      return {Op::kPvInsertB, Op::kPvInsertH, kFormSciH | kFormSciB, false, true};
    case 0x20:
      return {Op::kPvDotupB, Op::kPvDotupH, kAllForms, false};
    case 0x22:
      return {Op::kPvDotuspB, Op::kPvDotuspH, kAllForms, true};
    case 0x26:
      return {Op::kPvDotspB, Op::kPvDotspH, kAllForms, true};
    case 0x28:
      return {Op::kPvSdotupB, Op::kPvSdotupH, kAllForms, false, true};
    case 0x2A:
      return {Op::kPvSdotuspB, Op::kPvSdotuspH, kAllForms, true, true};
    case 0x2E:
      return {Op::kPvSdotspB, Op::kPvSdotspH, kAllForms, true, true};
    // shuffle: .h, .sci.h, .b; its .sci.b slot is pv.shuffleI0.sci.b (see DecodeShuffleI)
    case 0x30:
      return {Op::kPvShuffleB, Op::kPvShuffleH, kFormH | kFormB | kFormSciH, false};
    case 0x32:
      return {Op::kPvShuffle2B, Op::kPvShuffle2H, kFormH | kFormB, false, true};
    case 0x34:
      return {Op::kIllegal, Op::kPvPackH, kFormH};
    case 0x36:
      return {Op::kPvPackHiB, Op::kIllegal, kFormB, false, true};
    case 0x38:
      return {Op::kPvPackLoB, Op::kIllegal, kFormB, false, true};
    case 0x01:
      return {Op::kPvCmpEqB, Op::kPvCmpEqH, kAllForms, true};
    case 0x03:
      return {Op::kPvCmpNeB, Op::kPvCmpNeH, kAllForms, true};
    case 0x05:
      return {Op::kPvCmpGtB, Op::kPvCmpGtH, kAllForms, true};
    case 0x07:
      return {Op::kPvCmpGeB, Op::kPvCmpGeH, kAllForms, true};
    case 0x09:
      return {Op::kPvCmpLtB, Op::kPvCmpLtH, kAllForms, true};
    case 0x0B:
      return {Op::kPvCmpLeB, Op::kPvCmpLeH, kAllForms, true};
    case 0x0D:
      return {Op::kPvCmpGtuB, Op::kPvCmpGtuH, kAllForms, false};
    case 0x0F:
      return {Op::kPvCmpGeuB, Op::kPvCmpGeuH, kAllForms, false};
    case 0x11:
      return {Op::kPvCmpLtuB, Op::kPvCmpLtuH, kAllForms, false};
    case 0x13:
      return {Op::kPvCmpLeuB, Op::kPvCmpLeuH, kAllForms, false};
    default:
      return {};
  }
}

// The 6-bit immediate of the .sci forms: imm[0] = bit 25, imm[5:1] = bits 24..20 [GVSOC
// Ranges([[25, 1, 0], [20, 5, 1]])].
uint32_t SimdImm6(uint32_t w) { return (Bits(w, 24, 20) << 1) | Bits(w, 25, 25); }

// pv.shuffleI{k}.sci.b (funct6 110000, 111010, 111100, 111110 with funct3 111): the result's
// top byte is byte k of rs1, the others bytes I[5:4], I[3:2], I[1:0] [RI5CY; GVSOC
// lib_VEC_SHUFFLEI*_SCI_8]: the same as pv.shuffle.b with that selector.
Decoded DecodeShuffleI(uint32_t w, uint32_t k) {
  const uint32_t imm = SimdImm6(w);
  Decoded d = Base(w, Op::kPvShuffleB);
  d.scalar = 2;
  d.imm = static_cast<int32_t>((k << 24) | (((imm >> 4) & 3) << 16) | (((imm >> 2) & 3) << 8) |
                               (imm & 3));
  d.src_mask = RegBit(d.rs1);
  return d;
}

// GAP8's own SIMD extensions [GVSOC of gap_sdk, isa_riscv_gen.py subset `gap8`]; Illegal when
// the encoding is none of them. The .sc/.sci forms of pv.cplxmul.s and pv.vitop.max/sel stay
// illegal: their semantics are not established by the sources the model uses.
Decoded DecodeGap8Simd(uint32_t w) {
  const uint32_t f3 = Bits(w, 14, 12), f7 = Bits(w, 31, 25);
  auto make = [&](Op op, int32_t shift) {
    Decoded d = Base(w, op);
    d.imm = shift;
    return d;
  };
  if (f3 == 2 || f3 == 3) {  // the .div2 / .div4 forms: funct7 selects, funct3 011 = .b
    const bool b = f3 == 3;
    switch (f7) {
      case 0x00:
        return make(b ? Op::kPvAddDivB : Op::kPvAddDivH, 1);
      case 0x01:
        return make(b ? Op::kPvAddDivB : Op::kPvAddDivH, 2);
      case 0x04:
        return make(b ? Op::kPvSubDivB : Op::kPvSubDivH, 1);
      case 0x05:
        return make(b ? Op::kPvSubDivB : Op::kPvSubDivH, 2);
      case 0x2A:
        return b ? Illegal(w) : make(Op::kPvCplxMulS, 16);
      case 0x2B:
        return b ? Illegal(w) : make(Op::kPvCplxMulS, 17);
      case 0x36:
        return b ? Illegal(w) : make(Op::kPvSubRotmjH, 1);
      case 0x37:
        return b ? Illegal(w) : make(Op::kPvSubRotmjH, 2);
      default:
        return Illegal(w);
    }
  }
  if (f3 == 0 && (f7 >> 1) == 0x15) return make(Op::kPvCplxMulS, 15);
  if (f3 == 0 && (f7 >> 1) == 0x1B) return make(Op::kPvSubRotmjH, 0);
  if (f3 == 0 && f7 == 0x2E && Bits(w, 24, 20) == 0) {
    Decoded d = make(Op::kPvCplxConjH, 0);
    d.src_mask = RegBit(d.rs1);
    return d;
  }
  if ((f7 >> 1) == 0x34 && f3 == 6) return make(Op::kPvPackHH, 0);  // pv.pack.h.h
  if ((f7 >> 1) == 0x34 && f3 == 4) return make(Op::kPvPackH, 0);   // pv.pack.l.h
  return Illegal(w);
}

}  // namespace

Decoded DecodeXpulpSimd(uint32_t w) {
  const uint32_t f3 = Bits(w, 14, 12), funct6 = Bits(w, 31, 26);
  if (f3 == 7) {
    if (funct6 == 0x30) return DecodeShuffleI(w, 0);
    if (funct6 == 0x3A) return DecodeShuffleI(w, 1);
    if (funct6 == 0x3C) return DecodeShuffleI(w, 2);
    if (funct6 == 0x3E) return DecodeShuffleI(w, 3);
  }
  const SimdEntry e = SimdTable(funct6);
  if ((e.forms & (1u << f3)) == 0) return DecodeGap8Simd(w);
  const bool half = (f3 & 1) == 0;
  const Op op = half ? e.h : e.b;
  if (op == Op::kIllegal) return DecodeGap8Simd(w);
  // pv.abs and pv.pack.h have bit 25 fixed to 0 (funct7 0111000, 1101000) [GVSOC].
  if ((op == Op::kPvAbsB || op == Op::kPvAbsH || op == Op::kPvPackH) && Bits(w, 25, 25) != 0)
    return Illegal(w);
  Decoded d = Base(w, op);
  d.width = half ? 1 : 0;
  const bool sci = f3 >= 6, sc = f3 == 4 || f3 == 5;
  d.scalar = sci ? 2 : sc ? 1 : 0;
  if (sci) {
    const uint32_t imm6 = SimdImm6(w);
    const uint32_t value = e.sci_signed ? static_cast<uint32_t>(SignExtend(imm6, 6)) : imm6;
    uint32_t operand = half ? xpulp::SplatHalf(value) : xpulp::SplatByte(value);
    // extract / insert take the lane index, shuffle.sci.h the two selector bits I1, I0.
    if (op == Op::kPvExtractB || op == Op::kPvExtractH || op == Op::kPvExtractuB ||
        op == Op::kPvExtractuH || op == Op::kPvInsertB || op == Op::kPvInsertH)
      operand = imm6;
    if (op == Op::kPvShuffleH) operand = (((imm6 >> 1) & 1) << 16) | (imm6 & 1);
    d.imm = static_cast<int32_t>(operand);
    d.src_mask = RegBit(d.rs1);
  }
  if (op == Op::kPvAbsB || op == Op::kPvAbsH) d.src_mask = RegBit(d.rs1);
  if (e.reads_rd) d.src_mask |= RegBit(d.rd);
  return d;
}

// OP (0110011) with the PULPv2 funct7 values; RV32I/M funct7 0000000, 0100000, 0000001 are
// decoded by the caller.
Decoded DecodeXpulpAlu(uint32_t w) {
  const uint32_t f3 = Bits(w, 14, 12), f7 = Bits(w, 31, 25);
  auto one_source = [&](Op op) {
    if (Bits(w, 24, 20) != 0) return Illegal(w);
    Decoded d = Base(w, op);
    d.src_mask = RegBit(d.rs1);
    return d;
  };
  auto with_imm = [&](Op op, uint32_t operand) {
    Decoded d = Base(w, op);
    d.scalar = 2;
    d.imm = static_cast<int32_t>(operand);
    d.src_mask = RegBit(d.rs1);
    return d;
  };
  switch (f7) {
    case 0x02: {  // p.abs, p.avgu, p.slet(u), p.min(u), p.max(u)
      static constexpr Op kOps[8] = {Op::kPAbs, Op::kPAvgu, Op::kPSlet, Op::kPSletu,
                                     Op::kPMin, Op::kPMinu, Op::kPMax,  Op::kPMaxu};
      return f3 == 0 ? one_source(Op::kPAbs) : Base(w, kOps[f3]);
    }
    case 0x04:  // p.ror
      return f3 == 5 ? Base(w, Op::kPRor) : Illegal(w);
    case 0x08: {  // p.ff1, p.fl1, p.clb, p.cnt, p.exths, p.exthz, p.extbs, p.extbz
      static constexpr Op kOps[8] = {Op::kPFf1,   Op::kPFl1,   Op::kPClb,   Op::kPCnt,
                                     Op::kPExths, Op::kPExthz, Op::kPExtbs, Op::kPExtbz};
      return one_source(kOps[f3]);
    }
    case 0x0A:  // p.clip Is2 (001), p.clipu Is2 (010), p.clipr (101), p.clipur (110)
      if (f3 == 1) return with_imm(Op::kPClip, Bits(w, 24, 20));
      if (f3 == 2) return with_imm(Op::kPClipu, Bits(w, 24, 20));
      if (f3 == 5) return Base(w, Op::kPClipr);
      if (f3 == 6) return Base(w, Op::kPClipur);
      return Illegal(w);
    case 0x21:  // p.mac, p.msu: rD += / -= rs1 * rs2
      if (f3 > 1) return Illegal(w);
      {
        Decoded d = Base(w, f3 == 0 ? Op::kPMac : Op::kPMsu);
        d.src_mask |= RegBit(d.rd);
        return d;
      }
    case 0x40: {  // register bit-field forms: the field comes from rs2
      static constexpr Op kOps[8] = {Op::kPExtract, Op::kPExtractu, Op::kPInsert, Op::kPBclr,
                                     Op::kPBset,    Op::kIllegal,   Op::kIllegal, Op::kIllegal};
      if (kOps[f3] == Op::kIllegal) return Illegal(w);
      Decoded d = Base(w, kOps[f3]);
      if (kOps[f3] == Op::kPInsert) d.src_mask |= RegBit(d.rd);
      return d;
    }
    default:
      break;
  }
  if (Bits(w, 31, 30) == 3) {  // immediate bit-field forms: Is3 in bits 29..25, Is2 in 24..20
    static constexpr Op kOps[8] = {Op::kPExtract, Op::kPExtractu, Op::kPInsert, Op::kPBclr,
                                   Op::kPBset,    Op::kIllegal,   Op::kIllegal, Op::kIllegal};
    if (kOps[f3] == Op::kIllegal) return Illegal(w);
    Decoded d = with_imm(kOps[f3], (Bits(w, 29, 25) << 5) | Bits(w, 24, 20));
    if (kOps[f3] == Op::kPInsert) d.src_mask |= RegBit(d.rd);
    return d;
  }
  return Illegal(w);
}

// Opcode 1011011: 16-bit multiplies and MACs (funct3 x00 / x01, bit 14 = rounding) and the
// normalised add/sub (funct3 x10 / x11). Bits 31..30 select the variant, 29..25 hold Is3
// [GVSOC isa_pulpv2.py; RI5CY "MAC Encoding", "General ALU Encoding"].
Decoded DecodeXpulpMac(uint32_t w) {
  const uint32_t f3 = Bits(w, 14, 12), f2 = Bits(w, 31, 30), is3 = Bits(w, 29, 25);
  const bool round = (f3 & 4) != 0;
  if ((f3 & 3) <= 1) {
    const bool accumulate = (f3 & 3) == 1;
    Decoded d = Base(w, Op::kPMul16);
    // bits 31..30: 00 u (low halves), 01 hhu, 10 s, 11 hhs
    d.width = static_cast<uint8_t>(((f2 & 2) ? kMulSigned : 0) | ((f2 & 1) ? kMulHigh : 0) |
                                   (accumulate ? kMulAccumulate : 0) | (round ? kMulRound : 0));
    d.imm = static_cast<int32_t>(is3);
    if (accumulate) d.src_mask |= RegBit(d.rd);
    return d;
  }
  const bool subtract = (f3 & 3) == 3;
  // bits 31..30: 00 N (arithmetic), 10 uN (logical): immediate shift; 01, 11 with bits 29..25
  // zero: the register forms p.add[u][R]Nr, rD = (rD +/- rs1) >> rs2[4:0].
  const bool register_form = (f2 & 1) != 0;
  if (register_form && is3 != 0) return Illegal(w);
  Decoded d = Base(w, register_form ? Op::kPAddNr : Op::kPAddN);
  d.width = static_cast<uint8_t>((subtract ? kAddNSubtract : 0) | ((f2 & 2) ? 0 : kAddNSigned) |
                                 (round ? kAddNRound : 0));
  d.imm = static_cast<int32_t>(is3);
  if (register_form) d.src_mask |= RegBit(d.rd);
  return d;
}

// p.beqimm / p.bneimm rs1, imm5, label: branch funct3 010 / 011, imm5 (signed) in the rs2
// field [RI5CY "Immediate Branching"; GVSOC Format_SB2].
Decoded DecodeBranchImm(uint32_t w, int32_t offset) {
  Decoded d = Base(w, Bits(w, 14, 12) == 2 ? Op::kBeqImm : Op::kBneImm);
  d.imm = offset;
  d.rd = 0;
  d.src_mask = RegBit(d.rs1);
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
