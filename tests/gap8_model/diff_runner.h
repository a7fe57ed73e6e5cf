// Runs the model's core and Unicorn side by side from the same state and reports the first
// difference: pc or any register after an instruction, or memory at the end.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gap8/memory.h"
#include "unicorn_cpu.h"

struct DiffOutcome {
  bool same = true;
  uint64_t steps = 0;
  std::string difference;  // first difference, when !same
};

using Regions = std::vector<std::pair<uint32_t, uint32_t>>;  // (base, size)

// All of L1 and L2.
Regions WholeMemory();

// Both start from `memory` (the `regions` copied into Unicorn), pc `start` and registers `regs`;
// they run until pc reaches `end` or `max_steps` instructions ran (then the difference says
// so). The `regions` are compared at the end. Unicorn keeps code it translated: new code must
// go to addresses it has not run (or to a fresh UnicornCpu).
DiffOutcome RunDifferential(UnicornCpu& uc, gap8::Memory& memory, uint32_t start, uint32_t end,
                            const uint32_t (&regs)[32], uint64_t max_steps, const Regions& regions);
