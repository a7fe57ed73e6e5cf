// Decoder for 32-bit RV32IM and PULPv2 (Xpulp) loads and stores; the rest of PULPv2 is in
// decode_xpulp.cpp.
#include "decode_compressed.h"
#include "decode_fields.h"
#include "gap8/decoded.h"

namespace gap8 {

Decoded DecodeXpulpSimd(uint32_t w);
Decoded DecodeXpulpAlu(uint32_t w);
Decoded DecodeXpulpMac(uint32_t w);
Decoded DecodeBranchImm(uint32_t w, int32_t offset);
Decoded DecodeHwLoop(uint32_t w);

namespace {

int32_t ImmI(uint32_t w) { return SignExtend(Bits(w, 31, 20), 12); }
int32_t ImmS(uint32_t w) { return SignExtend((Bits(w, 31, 25) << 5) | Bits(w, 11, 7), 12); }
int32_t ImmB(uint32_t w) {
  return SignExtend((Bits(w, 31, 31) << 12) | (Bits(w, 7, 7) << 11) | (Bits(w, 30, 25) << 5) |
                        (Bits(w, 11, 8) << 1),
                    13);
}
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

// p.l* register-offset forms encode the width in funct7 instead of funct3.
int LoadWidthFromFunct7(uint32_t f7) {
  switch (f7) {
    case 0x00:
      return 0;
    case 0x08:
      return 1;
    case 0x10:
      return 2;
    case 0x20:
      return 4;
    case 0x28:
      return 5;
    default:
      return -1;
  }
}

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
  return DecodeXpulpAlu(w);  // PULPv2's funct7 values, or illegal
}

Decoded DecodeLoad(uint32_t w) {
  const uint32_t f3 = Bits(w, 14, 12);
  if (f3 == 7) {  // p.l* rd, rs2(rs1)
    int width = LoadWidthFromFunct7(Bits(w, 31, 25));
    if (width < 0) return Illegal(w);
    Decoded d = Base(w, Op::kLoadRegReg);
    d.width = width;
    return d;
  }
  if (f3 == 6) {  // p.elw rd, imm(rs1) [GVSOC p_elw_exec: "a regular load whose park puts the
                  // whole core to sleep until the event unit answers"]: the model's blocking
                  // peripheral reads already sleep, so it is lw with its own op
    Decoded d = WithImm(Base(w, Op::kElw), ImmI(w), false);
    d.width = 2;
    return d;
  }
  if (!ValidLoadWidth(f3)) return Illegal(w);
  Decoded d = WithImm(Base(w, Op::kLoad), ImmI(w), false);
  d.width = f3;
  return d;
}

// PULP custom-0 (0001011): post-incrementing loads.
Decoded DecodeLoadPost(uint32_t w) {
  const uint32_t f3 = Bits(w, 14, 12);
  if (f3 == 7) {
    int width = LoadWidthFromFunct7(Bits(w, 31, 25));
    if (width < 0) return Illegal(w);
    Decoded d = Base(w, Op::kLoadPostReg);
    d.width = width;
    return d;
  }
  if (!ValidLoadWidth(f3)) return Illegal(w);
  Decoded d = WithImm(Base(w, Op::kLoadPostImm), ImmI(w), false);
  d.width = f3;
  return d;
}

// Stores (0100011) and PULP custom-1 (0101011) post-incrementing stores; funct3 4..6 are the
// register-offset forms, whose offset register rs3 sits in the rd field.
Decoded DecodeStore(uint32_t w, bool post) {
  const uint32_t f3 = Bits(w, 14, 12);
  if (f3 <= 2) {
    Decoded d = WithImm(Base(w, post ? Op::kStorePostImm : Op::kStore), ImmS(w), true);
    d.rd = 0;
    d.width = f3;
    return d;
  }
  if (f3 >= 4 && f3 <= 6 && Bits(w, 31, 25) == 0) {
    Decoded d = Base(w, post ? Op::kStorePostReg : Op::kStoreRegReg);
    d.width = f3 - 4;
    d.src_mask |= RegBit(d.rd);
    return d;
  }
  return Illegal(w);
}

Decoded DecodeBranch(uint32_t w) {
  static constexpr Op kOps[8] = {Op::kBeq, Op::kBne, Op::kIllegal, Op::kIllegal,
                                 Op::kBlt, Op::kBge, Op::kBltu,    Op::kBgeu};
  const uint32_t f3 = Bits(w, 14, 12);
  if (f3 == 2 || f3 == 3) return DecodeBranchImm(w, ImmB(w));  // p.beqimm, p.bneimm
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
    case 0x0B:
      return DecodeLoadPost(w);
    case 0x23:
      return DecodeStore(w, false);
    case 0x2B:
      return DecodeStore(w, true);
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
    case 0x57:
      return DecodeXpulpSimd(w);
    case 0x5B:
      return DecodeXpulpMac(w);
    case 0x7B:
      return DecodeHwLoop(w);
    default:
      return Illegal(w);
  }
}

// The access facts of a load or store (see Decoded::access): what TcdmBankBit and ExecuteMemory
// need, without a switch on op per instruction.
void AddAccessFacts(Decoded& d) {
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
}

}  // namespace

Decoded Decode(uint32_t bits) {
  Decoded d = DecodeFields(bits);
  AddAccessFacts(d);
  return d;
}

}  // namespace gap8
