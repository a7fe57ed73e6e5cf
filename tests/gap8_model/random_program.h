// Seeded random RV32IMC instruction sequences for the differential test: random encodings of
// the computational, load/store and compressed classes (kept only when they decode to something
// safe to run: no writes to the base registers, memory only through them), plus forward
// branches and jumps whose targets are instruction boundaries of the sequence.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <vector>

struct RandomProgram {
  uint32_t start = 0;               // address of the first instruction (in L2)
  uint32_t end = 0;                 // address just past the last one
  std::vector<uint8_t> code;        // bytes at start
  std::array<uint32_t, 32> regs{};  // initial registers (x0 = 0)
  std::vector<uint8_t> data;        // initial bytes at kRandomDataBase (in L1)
};

inline constexpr uint32_t kRandomDataBase = 0x10000000u;
inline constexpr uint32_t kRandomDataSize = 0x4000u;

// The code goes to `code_base` (in L2); at most 8 bytes per instruction.
RandomProgram MakeRandomProgram(std::mt19937& rng, int instructions, uint32_t code_base);
