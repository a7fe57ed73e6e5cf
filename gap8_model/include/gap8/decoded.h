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
  kElw,           // p.elw rd, imm(rs1): a word load that sleeps until the event unit answers
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
  kBeqImm,  // p.beqimm / p.bneimm rs1, imm5, offset: imm5 (5 bits, signed) in the rs2 field
  kBneImm,
  // The rest of PULPv2 (see include/gap8/xpulp.h for each one's semantics and source), all
  // computed by EvaluateXpulp from (rs1, operand b, rd): operand b is rs2, rs2's low lane
  // replicated (.sc, Decoded::scalar 1) or the decoded immediate (.sci and the immediate
  // scalar forms, Decoded::scalar 2). Kept last: `op >= kXpulpEvaluated` selects them.
  kXpulpEvaluated,
  kPvAddH = kXpulpEvaluated,
  kPvSubH,
  kPvAvgB,
  kPvAvgH,
  kPvAvguH,
  kPvMinB,
  kPvMinH,
  kPvMinuH,
  kPvMaxB,
  kPvMaxH,
  kPvMaxuH,
  kPvSrlB,
  kPvSrlH,
  kPvSraB,
  kPvSraH,
  kPvSllB,
  kPvSllH,
  kPvOr,  // lane-independent: one op for .b and .h (only the .sc replication differs)
  kPvXor,
  kPvAnd,
  kPvAbsH,
  kPvExtractB,
  kPvExtractH,
  kPvExtractuB,
  kPvExtractuH,
  kPvInsertB,
  kPvInsertH,
  kPvDotupH,
  kPvDotuspH,
  kPvDotspB,
  kPvDotspH,
  kPvSdotupH,
  kPvSdotuspH,
  kPvSdotspB,
  kPvSdotspH,
  kPvShuffleB,  // also pv.shuffleI{0..3}.sci.b: the decoder builds the equivalent selector
  kPvShuffleH,
  kPvShuffle2B,
  kPvShuffle2H,
  kPvPackH,
  kPvPackHiB,
  kPvPackLoB,
  kPvCmpEqB,
  kPvCmpEqH,
  kPvCmpNeB,
  kPvCmpNeH,
  kPvCmpGtB,
  kPvCmpGtH,
  kPvCmpGeB,
  kPvCmpGeH,
  kPvCmpLtB,
  kPvCmpLtH,
  kPvCmpLeB,
  kPvCmpLeH,
  kPvCmpGtuB,
  kPvCmpGtuH,
  kPvCmpGeuB,
  kPvCmpGeuH,
  kPvCmpLtuB,
  kPvCmpLtuH,
  kPvCmpLeuB,
  kPvCmpLeuH,
  kPAvgu,
  kPSlet,
  kPSletu,
  kPRor,
  kPFf1,
  kPFl1,
  kPClb,
  kPCnt,
  kPExths,
  kPExthz,
  kPExtbs,
  kPExtbz,
  kPClip,  // operand b: Is2 (p.clip, p.clipu) or rs2 (p.clipr, p.clipur)
  kPClipu,
  kPClipr,
  kPClipur,
  kPExtract,  // operand b: the field, (width - 1) << 5 | position, from rs2 or Is3, Is2
  kPExtractu,
  kPInsert,
  kPBclr,
  kPBset,
  kPMac,
  kPMsu,
  // GAP8-only extensions [GVSOC of gap_sdk, isa_riscv_gen.py `gap8` subset, rvXgap8.hpp]:
  // Decoded::imm holds the right shift (div2 = 1, div4 = 2; cplxmul 15, 16, 17)
  kPvAddDivH,  // pv.add.h.div2 / .div4: per signed half-word (int16)(a + b) >> shift
  kPvAddDivB,
  kPvSubDivH,
  kPvSubDivB,
  kPvCplxMulS,  // pv.cplxmul.s[.div2/.div4]: Q15 complex product (re low, im high half)
  kPvCplxConjH,
  kPvSubRotmjH,  // pv.subrotmj.h[.div2/.div4]: (a - b) * -j
  kPvPackHH,     // pv.pack.h.h: rd = rs1[31:16] : rs2[31:16]
  kPMul16,       // p.mul{s,hhs,u,hhu}[R]N, p.mac{...}[R]N: Decoded::width holds Mul16Flags, imm Is3
  kPAddN,        // p.add[u][R]N, p.sub[u][R]N rD, rs1, rs2, Is3: width holds AddNFlags, imm Is3
  kPAddNr,       // the register forms: rD = (rD +/- rs1 [+ round]) >> rs2[4:0]
};

// Decoded::width of kPMul16 and kPAddN / kPAddNr.
enum Mul16Flags : uint8_t { kMulSigned = 1, kMulHigh = 2, kMulAccumulate = 4, kMulRound = 8 };
enum AddNFlags : uint8_t { kAddNSubtract = 1, kAddNSigned = 2, kAddNRound = 4 };

struct Decoded {
  Op op = Op::kUndecoded;
  uint8_t rd = 0;  // p.s* register-offset stores: the offset register rs3 (stores write no rd)
  uint8_t rs1 = 0;
  uint8_t rs2 = 0;
  int32_t imm = 0;
  uint32_t src_mask = 0;  // bit r set when the instruction reads register r (hazard checks)
  uint8_t size = 4;       // 2 for a compressed instruction
  uint8_t width = 0;      // loads and stores: RISC-V funct3 width code; SIMD: 1 for .h lanes
  uint8_t scalar = 0;     // operand b: 0 rs2, 1 rs2's low lane replicated (.sc), 2 imm (.sci)
  uint8_t loop = 0;       // lp.*: hardware loop index 0 or 1
  uint32_t raw = 0;       // the instruction bits, for fault messages
  // Facts derived from the fields above once, at decode time, so the per-cycle paths (bank
  // arbitration, ExecuteMemory) read them instead of switching on op every time.
  uint8_t access = 0;      // AccessFlags: does it load or store, and how the address is formed
  uint8_t offset_reg = 0;  // register added to rs1 to form the address (0: none; x0 reads 0)
};

enum AccessFlags : uint8_t {
  kAccessLoad = 1,       // any load (RV32I or p.l*)
  kAccessStore = 2,      // any store (RV32I or p.s*)
  kAccessImmOffset = 4,  // address = rs1 + imm (RV32I forms); else rs1 + offset_reg
};

// Decodes one instruction; `bits` holds 32 bits from the pc (the upper half is ignored when the
// low 16 bits are a compressed instruction).
Decoded Decode(uint32_t bits);

// The result of an instruction with op >= kXpulpEvaluated, from rs1's value a, operand b (rs2,
// its replicated low lane or the immediate, per Decoded::scalar) and rd's value c.
uint32_t EvaluateXpulp(const Decoded& d, uint32_t a, uint32_t b, uint32_t c);

// True when the 16-bit parcel starts a compressed instruction.
inline bool IsCompressed(uint32_t low16) { return (low16 & 3u) != 3u; }

}  // namespace gap8
