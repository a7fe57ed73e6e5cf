// The ISA table (isas.def) as C++ rows: what the host needs to list, probe, mask and run an ISA.
// isas.def is the one list of ISAs: C++ reads it here, CMake through isa_table.cmake.
#pragma once
#include <span>
#include <string>
#include <string_view>

#include "cpu_kernel.hpp"

namespace pxflow::cpu {

struct IsaInfo {
  const char* name;     // the row name: registry row, mask name, kernel file <name>.cpp
  const char* needs;    // for humans: "x86-64 with AVX2"
  const char* ceiling;  // the psadbw width it unlocks for the bench bound ("zmm"), or "none"
  // Both null for an ISA of another architecture (not compiled into this build).
  bool (*cpu_has)();             // the CPU feature test (CPUID, including the OS's state saving)
  const IsaKernel& (*kernel)();  // the accessor in <name>.cpp, compiled with its flags
  bool compiled() const { return kernel != nullptr; }
};

// Every row of isas.def, weakest first, on every architecture.
std::span<const IsaInfo> isa_table();

// The row named `name`, or null when the table has none.
const IsaInfo* find_isa(std::string_view name);

// Every name, comma-separated in table order, for error messages.
std::string known_isas();

}  // namespace pxflow::cpu
