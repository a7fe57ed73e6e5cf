// A lone core over a fresh memory, for executing hand-encoded instructions.
#pragma once

#include <cstdint>
#include <initializer_list>

#include "gap8/core.h"

struct CoreFixture {
  gap8::Memory memory;
  gap8::Core core{0, memory, nullptr};
  static constexpr uint32_t kCode = GAP8_L2_BASE + 0x100;

  // Places the instructions (32-bit words) at kCode and points pc at the first.
  void Load(std::initializer_list<uint32_t> words) {
    uint32_t addr = kCode;
    for (uint32_t w : words) {
      memory.Write(addr, &w, 4);
      addr += 4;
    }
    core.set_pc(kCode);
  }
  // Runs one instruction with rs1 = a, rs2 = b (registers 11 and 12), result in 10.
  uint32_t RunR(uint32_t word, uint32_t a, uint32_t b, uint32_t rd_before = 0) {
    Load({word});
    core.set_reg(10, rd_before);
    core.set_reg(11, a);
    core.set_reg(12, b);
    core.Step();
    return core.reg(10);
  }
};

// R-type encoding: funct7 rs2 rs1 funct3 rd opcode.
constexpr uint32_t EncodeR(uint32_t opcode, uint32_t funct3, uint32_t funct7, uint32_t rd,
                           uint32_t rs1, uint32_t rs2) {
  return (funct7 << 25) | (rs2 << 20) | (rs1 << 15) | (funct3 << 12) | (rd << 7) | opcode;
}
// I-type encoding.
constexpr uint32_t EncodeI(uint32_t opcode, uint32_t funct3, uint32_t rd, uint32_t rs1,
                           int32_t imm) {
  return (static_cast<uint32_t>(imm & 0xFFF) << 20) | (rs1 << 15) | (funct3 << 12) | (rd << 7) |
         opcode;
}
