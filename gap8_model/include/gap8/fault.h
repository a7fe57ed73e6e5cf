// A simulated program's fault: ends the run with one message naming core, pc and instruction.
#pragma once

#include <cstdint>
#include <string>

namespace gap8 {

// kHardwareLoop: a hardware loop breaks a rule of the RI5CY manual (see Core::ExecuteHwLoopSetup).
enum class FaultKind { kIllegalInstruction, kMemory, kCycleBudget, kDeadlock, kHardwareLoop };

struct Fault {
  FaultKind kind;
  int core;
  uint32_t pc;
  uint32_t insn;
  std::string what;     // the reason alone, e.g. "illegal instruction"
  bool fetched = true;  // false for a fetch fault: no instruction at pc, insn 0

  // "core 3 at pc 0x1c000104 (insn 0x0005a503: lw a0,0(a1)): load of 4 bytes from unmapped
  // address 0x30000000"; the instruction in assembly from the disassembler (gap8/disasm.h),
  // "unknown" where no instruction of the tables has these bits; "(insn 0x00000000)" alone
  // after a fetch fault.
  std::string Message() const;
};

const char* FaultKindName(FaultKind kind);

// "0x1c000104": addresses and instruction bits in messages.
std::string Hex(uint32_t value);

}  // namespace gap8
