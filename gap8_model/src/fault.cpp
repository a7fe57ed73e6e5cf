#include "gap8/fault.h"

#include <cstdio>

#include "gap8/disasm.h"

namespace gap8 {

std::string Hex(uint32_t value) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", value);
  return buf;
}

std::string Fault::Message() const {
  const std::string assembly = fetched ? ": " + DisassembleText(insn, pc) : "";
  return "core " + std::to_string(core) + " at pc " + Hex(pc) + " (insn " + Hex(insn) + assembly +
         "): " + what;
}

const char* FaultKindName(FaultKind kind) {
  switch (kind) {
    case FaultKind::kIllegalInstruction:
      return "illegal instruction";
    case FaultKind::kMemory:
      return "memory fault";
    case FaultKind::kCycleBudget:
      return "cycle budget exceeded";
    case FaultKind::kDeadlock:
      return "deadlock";
    case FaultKind::kHardwareLoop:
      return "hardware loop rule violated";
  }
  return "fault";
}

}  // namespace gap8
