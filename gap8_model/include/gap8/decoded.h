// One decoded instruction: what the interpreter executes and the decode cache stores.
#pragma once

#include <cstdint>

namespace gap8 {

enum class Op : uint8_t {
  kUndecoded = 0,  // decode-cache slot not filled yet; must stay zero
  kIllegal,
  // RV32I
  kLui,
  kAuipc,
  kJal,
  kJalr,
  kBeq,
  kBne,
  kBlt,
  kBge,
  kBltu,
  kBgeu,
  kLoad,   // width in Decoded::width: 0 lb, 1 lh, 2 lw, 4 lbu, 5 lhu (RISC-V funct3)
  kStore,  // width: 0 sb, 1 sh, 2 sw
  kAddi,
  kSlti,
  kSltiu,
  kXori,
  kOri,
  kAndi,
  kSlli,
  kSrli,
  kSrai,
  kAdd,
  kSub,
  kSll,
  kSlt,
  kSltu,
  kXor,
  kSrl,
  kSra,
  kOr,
  kAnd,
  kFence,
  kCsrRead,  // only reads of mhartid (csrrs rd, mhartid, x0) are modelled
  // RV32M
  kMul,
  kMulh,
  kMulhsu,
  kMulhu,
  kDiv,
  kDivu,
  kRem,
  kRemu,
  // Xpulp (PULPv2 encodings as used by GAP8's RI5CY cores): kept last, so `op >= kLoadPostImm`
  // tells an Xpulp instruction (the differential tests rely on it).
  kLoadPostImm,
  kLoadRegReg,
  kLoadPostReg,  // p.l* rd, imm(rs1!) / rs2(rs1) / rs2(rs1!)
  kStorePostImm,
  kStoreRegReg,
  kStorePostReg,  // p.s* rs2, imm(rs1!) / rs3(rs1) / rs3(rs1!)
  kPAbs,
  kPMin,
  kPMinu,
  kPMax,
  kPMaxu,
  kPvAddB,
  kPvSubB,
  kPvAvguB,
  kPvMinuB,
  kPvMaxuB,
  kPvAbsB,
  kPvDotupB,
  kPvDotuspB,
  kPvSdotupB,
  kPvSdotuspB,
  kLpStarti,
  kLpEndi,
  kLpCount,
  kLpCounti,
  kLpSetup,
  kLpSetupi,
};

struct Decoded {
  Op op = Op::kUndecoded;
  uint8_t rd = 0;  // p.s* register-offset stores: the offset register rs3 (stores write no rd)
  uint8_t rs1 = 0;
  uint8_t rs2 = 0;
  int32_t imm = 0;
  uint32_t src_mask = 0;  // bit r set when the instruction reads register r (hazard checks)
  uint8_t size = 4;       // 2 for a compressed instruction
  uint8_t width = 0;      // loads and stores: RISC-V funct3 width code
  uint8_t scalar = 0;     // pv.*.sc: operand b is rs2's low byte replicated
  uint8_t loop = 0;       // lp.*: hardware loop index 0 or 1
  uint32_t raw = 0;       // the instruction bits, for fault messages
};

// Decodes one instruction; `bits` holds 32 bits from the pc (the upper half is ignored when the
// low 16 bits are a compressed instruction).
Decoded Decode(uint32_t bits);

// True when the 16-bit parcel starts a compressed instruction.
inline bool IsCompressed(uint32_t low16) { return (low16 & 3u) != 3u; }

}  // namespace gap8
