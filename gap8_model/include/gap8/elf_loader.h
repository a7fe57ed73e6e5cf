// Loads a RISC-V ELF32 executable into the model's memory through elfutils' libelf.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <stdexcept>
#include <string>

#include "gap8/memory.h"

namespace gap8 {

struct ElfImage {
  uint32_t entry = 0;
  std::map<std::string, uint32_t> symbols;  // function and object symbols by name
};

// One-line reason why a file cannot be loaded (missing, not ELF32 RISC-V, segment outside L1/L2).
class ElfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

ElfImage LoadElf(const std::string& path, Memory& memory);

// The same from bytes in memory (an ELF embedded in a program); `name` names it in errors.
ElfImage LoadElfBytes(const std::string& name, std::span<const uint8_t> bytes, Memory& memory);

}  // namespace gap8
