// Every cycle cost the model charges, in one place. docs/gap8-model.md gives the source of each.
#pragma once

#include <cstdint>

namespace gap8::timing {

// RI5CY pipeline, after GVSOC's RI5CY timing and the RI5CY / CV32E40P user manual.
inline constexpr uint32_t kAlu = 1;           // ALU, SIMD and p.* instructions
inline constexpr uint32_t kLoadStore = 1;     // TCDM load or store
inline constexpr uint32_t kLoadUseStall = 1;  // next instruction reads the loaded register
inline constexpr uint32_t kMulUseStall = 1;   // next instruction reads the mul result
inline constexpr uint32_t kJumpRegStall = 1;  // jalr reads the register written just before
inline constexpr uint32_t kMulh = 5;          // mulh, mulhsu, mulhu
inline constexpr uint32_t kBranchNotTaken = 1;
inline constexpr uint32_t kBranchTaken = 3;
inline constexpr uint32_t kJump = 2;        // jal, jalr
inline constexpr uint32_t kMisaligned = 1;  // extra cycle: the access is split in two
inline constexpr uint32_t kHwLoopBackEdge = 0;

// Cluster side: this model's documented choices (GAP8 publishes no cycle-exact figures).
inline constexpr uint32_t kL2Access = 10;         // whole cost of one L2 load or store from a core
inline constexpr uint32_t kPeriphAccess = 2;      // event unit, DMA, counters, control registers
inline constexpr uint32_t kWakeUp = 2;            // from the waking event to the first instruction
inline constexpr uint32_t kDmaSetup = 20;         // per transfer, before the first byte moves
inline constexpr uint32_t kDmaRowSetup = 2;       // per row of a 2-D transfer
inline constexpr uint32_t kDmaBytesPerCycle = 8;  // 64-bit cluster DMA data path

// div, divu, rem, remu: GVSOC's RI5CY divider formula (serial divider, leading zeros skipped).
inline uint32_t Divide(uint32_t divisor, bool is_signed) {
  if (divisor == 0) return 1;
  const int32_t s = static_cast<int32_t>(divisor);
  if (is_signed && s < 0) return static_cast<uint32_t>(__builtin_clz(0u - divisor)) + 2;
  return static_cast<uint32_t>(__builtin_clz(divisor)) + 3;
}

}  // namespace gap8::timing
