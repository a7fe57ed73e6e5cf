// The decoder: the first row of gap8_model/isa/rv32imc.tbl that fits (RVC parcels expand to
// their 32-bit op), else the Xpulp rows (DecodeXpulp, from isa/xpulp.tbl). A row gives the op,
// the immediate's kind, the width and which fields are rd, rs1, rs2 and the registers read;
// this file only assembles the Decoded.
#include "decode_fields.h"
#include "gap8/decoded.h"

namespace gap8 {

namespace {

struct RvRow {
  uint32_t match, mask;
  Op op;
  uint8_t size;  // 2: an RVC parcel
  RvImm imm;
  int8_t width;        // loads and stores: -1 funct3 (bits 14..12), else this width
  Field rd, rs1, rs2;  // the Decoded's register slots (kNoField: x0)
  uint8_t reads;       // Field bits: the source mask
};

constexpr RvRow kRows[] = {
#include "gap8/rv32imc_decode.inc"
};

Decoded FromRow(const RvRow& r, uint32_t w) {
  Decoded d;
  d.op = r.op;
  d.raw = w;
  d.size = r.size;
  if (r.op == Op::kIllegal) return d;  // c.unimp, a reserved encoding
  d.rd = static_cast<uint8_t>(FieldRegister(r.rd, w));
  d.rs1 = static_cast<uint8_t>(FieldRegister(r.rs1, w));
  d.rs2 = static_cast<uint8_t>(FieldRegister(r.rs2, w));
  d.src_mask = FieldsMask(r.reads, w);
  d.imm = RvImmediate(r.imm, w);
  d.width = static_cast<uint8_t>(r.width < 0 ? Bits(w, 14, 12) : static_cast<uint32_t>(r.width));
  return d;
}

Decoded DecodeFields(uint32_t bits) {
  const bool rvc = IsCompressed(bits & 0xFFFFu);
  const uint32_t w = rvc ? bits & 0xFFFFu : bits;
  const uint8_t size = rvc ? 2 : 4;
  for (const RvRow& r : kRows)
    if (r.size == size && (w & r.mask) == r.match) return FromRow(r, w);
  if (!rvc) return DecodeXpulp(w);
  Decoded d;  // no RVC row fits: floating point, RV64, reserved
  d.op = Op::kIllegal;
  d.raw = w;
  d.size = 2;
  return d;
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
  const bool hwloop_setup = d.op == Op::kLpStarti || d.op == Op::kLpEndi || d.op == Op::kLpCount ||
                            d.op == Op::kLpCounti || d.op == Op::kLpSetup || d.op == Op::kLpSetupi;
  if (d.access == 0 && d.op != Op::kIllegal && !hwloop_setup) d.access = kAccessOwnState;
}

}  // namespace

Decoded Decode(uint32_t bits) {
  Decoded d = DecodeFields(bits);
  AddDerivedFacts(d);
  return d;
}

}  // namespace gap8
