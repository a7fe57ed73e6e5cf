// One decoded instruction: what the interpreter executes and the decode cache stores.
#pragma once

#include <cstdint>

namespace gap8 {

enum class Op : uint8_t {
  kUndecoded = 0,  // decode-cache slot not filled yet; must stay zero
  kIllegal,
// RV32IMC: one entry per op of gap8_model/isa/rv32imc.tbl (an RVC instruction decodes to the
// op of its expansion), generated. kLoad / kStore: the width in Decoded::width; kCsrRead: only
// reads of mhartid (csrrs rd, mhartid, x0) are modelled.
#define GAP8_RV32IMC_OP(name) k##name,
#include "gap8/rv32imc_ops.inc"
#undef GAP8_RV32IMC_OP
// Xpulp (PULPv2 and GAP8's own extensions): one entry per op of gap8_model/isa/xpulp.tbl,
// generated. Their order means nothing: IsXpulp tells them from the RV32IM ops.
#define GAP8_XPULP_OP(name) k##name,
#include "gap8/xpulp_ops.inc"
#undef GAP8_XPULP_OP
};

// True for the ops of gap8_model/isa/xpulp.tbl (the differential tests leave them out: Unicorn
// does not know Xpulp).
constexpr bool IsXpulp(Op op) {
  switch (op) {
#define GAP8_XPULP_OP(name) case Op::k##name:
#include "gap8/xpulp_ops.inc"
#undef GAP8_XPULP_OP
    return true;
    default:
      return false;
  }
}

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
  // arbitration, ExecuteMemory, the issue loops) read them instead of computing them each time.
  uint8_t access = 0;      // AccessFlags: does it load or store, how the address is formed
  uint8_t offset_reg = 0;  // register added to rs1 to form the address (0: none; x0 reads 0)
  uint8_t tcdm = 0;        // 1 for any load or store (it asks for a TCDM bank when in L1)
  uint8_t rvc = 0;         // 1 for a compressed instruction (size 2): counted in RVC
  int32_t access_imm = 0;  // added to rs1 + offset_reg to form the address: imm or 0
  uint32_t rd_bit = 0;     // 1 << rd, 0 for x0: the register a pending result stalls readers of
};

enum AccessFlags : uint8_t {
  kAccessLoad = 1,       // any load (RV32I or p.l*)
  kAccessStore = 2,      // any store (RV32I or p.s*)
  kAccessImmOffset = 4,  // address = rs1 + imm (RV32I forms); else rs1 + offset_reg
  // None of the above: neither a memory access nor a hardware-loop set-up nor illegal, so it
  // reads and writes only its core's registers, pc and counters (Core::OwnStateOnly).
  kAccessOwnState = 8,
};

// Decodes one instruction; `bits` holds 32 bits from the pc (the upper half is ignored when the
// low 16 bits are a compressed instruction).
Decoded Decode(uint32_t bits);

// The result of an Xpulp instruction of path `eval` in xpulp.tbl, from rs1's value a, operand b
// (rs2, its replicated low lane or the immediate, per Decoded::scalar) and rd's value c.
uint32_t EvaluateXpulp(const Decoded& d, uint32_t a, uint32_t b, uint32_t c);

// True when the 16-bit parcel starts a compressed instruction.
inline bool IsCompressed(uint32_t low16) { return (low16 & 3u) != 3u; }

}  // namespace gap8
