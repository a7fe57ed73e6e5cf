// The model's disassembler, generated from its instruction tables (gap8_model/isa/rv32imc.tbl
// and xpulp.tbl, by isa/gen_disasm.py): the assembly text of an instruction and the registers
// it reads and writes, as the tables' operand-format column gives them. Used in fault messages
// and by gap8-run --trace.
#pragma once

#include <cstdint>
#include <string>

#include "gap8/decoded.h"

namespace gap8 {

struct Disassembly {
  bool known = false;    // a row of the tables fits (and is not a reserved encoding)
  uint8_t size = 4;      // bytes: 2 for an RVC parcel
  Op op = Op::kIllegal;  // the row's op (Decoded::op of the same bits)
  // "p.lw a0,4(a1!)" (GNU objdump -M no-aliases style); "c.unimp" or "reserved" for the
  // encodings the tables name but the model refuses; "unknown" where no row fits.
  std::string text;
  uint32_t reads = 0;           // bit r set when register r is read (x0 never)
  uint32_t writes = 0;          // bit r set when register r is written (x0 never)
  bool post_increment = false;  // an address form (rs1!): rs1 is written too
};

// `bits`: 32 bits from `pc` (the upper half is ignored when the low 16 bits are an RVC
// parcel); pc places branch and jump targets.
Disassembly Disassemble(uint32_t bits, uint32_t pc);

// The text alone: "lw t0,0(a0)", or "unknown".
inline std::string DisassembleText(uint32_t bits, uint32_t pc) {
  return Disassemble(bits, pc).text;
}

}  // namespace gap8
