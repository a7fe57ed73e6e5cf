// Decoder for 32-bit RV32IM; the Xpulp encodings go to DecodeXpulp (decode_xpulp.cpp, from the
// rows of gap8_model/isa/xpulp.tbl).
#include "decode_compressed.h"
#include "decode_fields.h"
#include "gap8/decoded.h"

namespace gap8 {

namespace {

int32_t ImmJ(uint32_t w) {
  return SignExtend((Bits(w, 31, 31) << 20) | (Bits(w, 19, 12) << 12) | (Bits(w, 20, 20) << 11) |
                        (Bits(w, 30, 21) << 1),
                    21);
}

Decoded WithImm(Decoded d, int32_t imm, bool reads_rs2) {
  d.imm = imm;
  if (!reads_rs2) d.src_mask = RegBit(d.rs1);
  return d;
}

// U and J formats: the rs1/rs2 bit positions belong to the immediate.
Decoded NoSources(Decoded d, int32_t imm) {
  d.imm = imm;
  d.src_mask = 0;
  return d;
}

Decoded Illegal(uint32_t w) {
  Decoded d;
  d.op = Op::kIllegal;
  d.raw = w;
  return d;
}

// Load widths allowed in RISC-V funct3 terms: lb, lh, lw, lbu, lhu.
bool ValidLoadWidth(uint32_t f3) { return f3 <= 2 || f3 == 4 || f3 == 5; }

Decoded DecodeOpImm(uint32_t w) {
  const uint32_t f3 = Bits(w, 14, 12), f7 = Bits(w, 31, 25);
  static constexpr Op kOps[8] = {Op::kAddi, Op::kSlli, Op::kSlti, Op::kSltiu,
                                 Op::kXori, Op::kSrli, Op::kOri,  Op::kAndi};
  Op op = kOps[f3];
  if (f3 == 1 && f7 != 0) return Illegal(w);
  if (f3 == 5) {
    if (f7 == 0x20)
      op = Op::kSrai;
    else if (f7 != 0)
      return Illegal(w);
  }
  int32_t imm = (f3 == 1 || f3 == 5) ? static_cast<int32_t>(Bits(w, 24, 20)) : ImmI(w);
  return WithImm(Base(w, op), imm, false);
}

Decoded DecodeOp(uint32_t w) {
  const uint32_t f3 = Bits(w, 14, 12), f7 = Bits(w, 31, 25);
  if (f7 == 0x00) {
    static constexpr Op kOps[8] = {Op::kAdd, Op::kSll, Op::kSlt, Op::kSltu,
                                   Op::kXor, Op::kSrl, Op::kOr,  Op::kAnd};
    return Base(w, kOps[f3]);
  }
  if (f7 == 0x20 && (f3 == 0 || f3 == 5)) return Base(w, f3 == 0 ? Op::kSub : Op::kSra);
  if (f7 == 0x01) {
    static constexpr Op kOps[8] = {Op::kMul, Op::kMulh, Op::kMulhsu, Op::kMulhu,
                                   Op::kDiv, Op::kDivu, Op::kRem,    Op::kRemu};
    return Base(w, kOps[f3]);
  }
  return DecodeXpulp(w);  // PULPv2's funct7 values, or illegal
}

// RV32I loads; LOAD funct3 6 (p.elw) and 7 (p.l* rd, rs2(rs1)) are Xpulp.
Decoded DecodeLoad(uint32_t w) {
  const uint32_t f3 = Bits(w, 14, 12);
  if (f3 >= 6) return DecodeXpulp(w);
  if (!ValidLoadWidth(f3)) return Illegal(w);
  Decoded d = WithImm(Base(w, Op::kLoad), ImmI(w), false);
  d.width = f3;
  return d;
}

// RV32I stores; STORE funct3 4..6 (p.s* rs2, rs3(rs1)) are Xpulp.
Decoded DecodeStore(uint32_t w) {
  const uint32_t f3 = Bits(w, 14, 12);
  if (f3 > 2) return DecodeXpulp(w);
  Decoded d = WithImm(Base(w, Op::kStore), ImmS(w), true);
  d.rd = 0;
  d.width = f3;
  return d;
}

Decoded DecodeBranch(uint32_t w) {
  static constexpr Op kOps[8] = {Op::kBeq, Op::kBne, Op::kIllegal, Op::kIllegal,
                                 Op::kBlt, Op::kBge, Op::kBltu,    Op::kBgeu};
  const uint32_t f3 = Bits(w, 14, 12);
  if (f3 == 2 || f3 == 3) return DecodeXpulp(w);  // p.beqimm, p.bneimm
  Op op = kOps[f3];
  if (op == Op::kIllegal) return Illegal(w);
  Decoded d = WithImm(Base(w, op), ImmB(w), true);
  d.rd = 0;
  return d;
}

Decoded DecodeSystem(uint32_t w) {
  // csrrs rd, mhartid, x0 (csrr rd, mhartid) is the only system instruction the model runs.
  if (Bits(w, 14, 12) == 2 && Bits(w, 31, 20) == 0xF14 && Bits(w, 19, 15) == 0) {
    Decoded d = Base(w, Op::kCsrRead);
    d.src_mask = 0;
    return d;
  }
  return Illegal(w);
}

Decoded DecodeFields(uint32_t bits) {
  if (IsCompressed(bits & 0xFFFFu)) return DecodeCompressed(bits & 0xFFFFu);
  const uint32_t w = bits;
  switch (Bits(w, 6, 0)) {
    case 0x37:
      return NoSources(Base(w, Op::kLui), static_cast<int32_t>(w & 0xFFFFF000u));
    case 0x17:
      return NoSources(Base(w, Op::kAuipc), static_cast<int32_t>(w & 0xFFFFF000u));
    case 0x6F:
      return NoSources(Base(w, Op::kJal), ImmJ(w));
    case 0x67:
      if (Bits(w, 14, 12) != 0) return Illegal(w);
      return WithImm(Base(w, Op::kJalr), ImmI(w), false);
    case 0x63:
      return DecodeBranch(w);
    case 0x03:
      return DecodeLoad(w);
    case 0x23:
      return DecodeStore(w);
    case 0x13:
      return DecodeOpImm(w);
    case 0x33:
      return DecodeOp(w);
    case 0x0F: {  // fence and fence.i: no effect on an in-order core without caches
      if (Bits(w, 14, 12) > 1) return Illegal(w);
      Decoded d = Base(w, Op::kFence);
      d.rd = 0;
      d.src_mask = 0;
      return d;
    }
    case 0x73:
      return DecodeSystem(w);
    case 0x0B:  // PULP custom-0: post-incrementing loads
    case 0x2B:  // PULP custom-1: post-incrementing stores
    case 0x57:  // packed SIMD
    case 0x5B:  // 16-bit MACs, normalised add/sub
    case 0x7B:  // hardware loops
      return DecodeXpulp(w);
    default:
      return Illegal(w);
  }
}

// The derived facts (see Decoded::access and below): what TcdmBankBit, ExecuteMemory and the
// interpreter need, without a switch on op or a shift per instruction.
void AddDerivedFacts(Decoded& d) {
  switch (d.op) {
    case Op::kLoad:
    case Op::kElw:
      d.access = kAccessLoad | kAccessImmOffset;
      break;
    case Op::kStore:
      d.access = kAccessStore | kAccessImmOffset;
      break;
    case Op::kLoadRegReg:
      d.access = kAccessLoad;
      d.offset_reg = d.rs2;
      break;
    case Op::kStoreRegReg:
      d.access = kAccessStore;
      d.offset_reg = d.rd;  // rs3
      break;
    case Op::kLoadPostImm:
    case Op::kLoadPostReg:
      d.access = kAccessLoad;  // post-increment: the address is rs1 unmodified
      break;
    case Op::kStorePostImm:
    case Op::kStorePostReg:
      d.access = kAccessStore;
      break;
    default:
      break;
  }
  d.tcdm = (d.access & (kAccessLoad | kAccessStore)) != 0;
  d.access_imm = (d.access & kAccessImmOffset) ? d.imm : 0;
  d.rvc = d.size == 2;
  d.rd_bit = (1u << d.rd) & ~1u;
}

}  // namespace

Decoded Decode(uint32_t bits) {
  Decoded d = DecodeFields(bits);
  AddDerivedFacts(d);
  return d;
}

}  // namespace gap8
