// The interpreter's main switch (generated from isa/rv32imc.tbl and isa/xpulp.tbl): RV32I, the
// control flow and the Xpulp arithmetic, inline so
// that the cluster's issue loops run it without a call (Core::Execute is the same, out of line).
// The TCDM path of loads and stores too; M-extension, branches, hardware-loop set-up and the rest
// of the memory path live in their own functions.
#pragma once

#include <cstring>

#include "gap8/core.h"
#include "gap8/timing.h"
#include "gap8/xpulp.h"
#include "xpulp_semantics.h"

namespace gap8 {
namespace execute_detail {

// Operand b of an Xpulp instruction (see Decoded::scalar): rs2, rs2's low lane replicated
// (.sc) or the immediate the decoder prepared (.sci, immediate scalar forms).
inline uint32_t OperandB(const Decoded& d, uint32_t rs2_value) {
  if (d.scalar == 0) return rs2_value;
  if (d.scalar == 2) return static_cast<uint32_t>(d.imm);
  return d.width ? xpulp::SplatHalf(rs2_value) : xpulp::SplatByte(rs2_value);
}

inline uint32_t AccessBytes(uint8_t width) { return 1u << (width & 3u); }

// Fixed-size copies, so the compiler emits plain moves instead of a memcpy call.
inline uint32_t ReadBytes(const uint8_t* p, uint32_t bytes) {
  if (bytes == 4) {
    uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
  }
  if (bytes == 2) {
    uint16_t v;
    std::memcpy(&v, p, 2);
    return v;
  }
  return *p;
}

inline void WriteBytes(uint8_t* p, uint32_t value, uint32_t bytes) {
  if (bytes == 4) {
    std::memcpy(p, &value, 4);
  } else if (bytes == 2) {
    const uint16_t v = static_cast<uint16_t>(value);
    std::memcpy(p, &v, 2);
  } else {
    *p = static_cast<uint8_t>(value);
  }
}

inline uint32_t Extend(uint32_t raw, uint8_t width) {
  switch (width) {
    case 0:
      return static_cast<uint32_t>(static_cast<int8_t>(raw));
    case 1:
      return static_cast<uint32_t>(static_cast<int16_t>(raw));
    default:
      return raw;  // lw, lbu, lhu: the raw bytes, zero-extended
  }
}

}  // namespace execute_detail

// Loads and stores (RV32I and the PULP post-increment / register-offset forms): TCDM here, the
// rest (L2, peripherals, faults) out of line in core_memory.cpp. The access is counted (LD, ST)
// before it happens: a peripheral access may read the counters.
inline uint32_t Core::ExecuteMemory(const Decoded& d) {
  using namespace execute_detail;
  const uint32_t addr = AccessAddress(d);
  const uint32_t bytes = AccessBytes(d.width);
  const bool misaligned = (addr & (bytes - 1)) != 0;
  uint8_t* const l1 = mem_.L1Span(addr, bytes);
  uint32_t cost = timing::kLoadStore + (misaligned ? timing::kMisaligned : 0);  // in TCDM
  const uint32_t next = pc_ + d.size;
  if (d.access & kAccessStore) {
    const uint32_t value = regs_[d.rs2];
    events_[GAP8_EVT_ST] += misaligned ? 2 : 1;
    if (l1) {
      WriteBytes(l1, value, bytes);
      mem_.InvalidateCode(addr, bytes);  // L1 may hold code too
    } else {
      StoreOutsideL1(addr, bytes, misaligned, value, &cost);
    }
    ClearHazard();
    if (d.op == Op::kStorePostImm) regs_[d.rs1] = addr + static_cast<uint32_t>(d.imm);
    if (d.op == Op::kStorePostReg) regs_[d.rs1] = addr + regs_[d.rd];
  } else {
    events_[GAP8_EVT_LD] += misaligned ? 2 : 1;
    const uint32_t raw = l1 ? ReadBytes(l1, bytes) : LoadOutsideL1(addr, bytes, misaligned, &cost);
    const uint32_t value = Extend(raw, d.width);
    if (d.op == Op::kLoadPostImm) regs_[d.rs1] = addr + static_cast<uint32_t>(d.imm);
    if (d.op == Op::kLoadPostReg) regs_[d.rs1] = addr + regs_[d.rs2];
    regs_[d.rd] = value;  // written last: with rd == rs1 the loaded value wins
    SetHazardBit(Hazard::kLoad, d.rd_bit);
    if (asleep) ClearHazard();  // a blocking peripheral read delivers at wake-up
    if (asleep) wake_rd = d.rd;
  }
  regs_[0] = 0;
  pc_ = NextSequentialPc(next);
  return cost;
}

// jal and jalr (a: rs1's value, imm: the offset).
[[gnu::always_inline]] inline uint32_t Core::ExecuteJump(const Decoded& d, uint32_t a,
                                                         uint32_t imm) {
  if (loops_armed_ && AtActiveLoopEnd())
    RaiseHwLoop("the last instruction of a hardware loop must not be a jump");
  ++events_[GAP8_EVT_JUMP];
  const uint32_t target = d.op == Op::kJal ? pc_ + imm : (a + imm) & ~1u;
  regs_[d.rd] = pc_ + d.size;
  regs_[0] = 0;
  pc_ = target;
  return timing::kJump;
}

[[gnu::always_inline]] inline uint32_t Core::ExecuteInline(const Decoded& d) {
  using execute_detail::OperandB;
  current_ = &d;
  ++events_[GAP8_EVT_INSTR];
  events_[GAP8_EVT_RVC] += d.rvc;
  SetHazardBit(Hazard::kAlu, d.rd_bit);
  const uint32_t a = regs_[d.rs1], b = regs_[d.rs2];
  const uint32_t imm = static_cast<uint32_t>(d.imm);
  uint32_t result;
  switch (d.op) {
    // RV32IMC: one generated case per op of gap8_model/isa/rv32imc.tbl, by its class and
    // semantics.
#include "gap8/rv32imc_execute.inc"
    // Xpulp: one generated case per op of gap8_model/isa/xpulp.tbl, by its class and path.
#include "gap8/xpulp_execute.inc"
    case Op::kIllegal:
    case Op::kUndecoded:
      Raise(FaultKind::kIllegalInstruction, "illegal instruction");
    default:  // every Op has its case: the jump table needs no range test
      __builtin_unreachable();
  }
  regs_[d.rd] = result;
  regs_[0] = 0;
  pc_ = NextSequentialPc(pc_ + d.size);
  return timing::kAlu;
}

}  // namespace gap8
