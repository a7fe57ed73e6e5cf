// A test-side assembler for Xpulp mnemonics: the encodings come from GreenWaves' assembler
// table (xgap8_opcodes.txt, test data copied from its opcode table), never from the model's
// own table (gap8_model/isa/xpulp.tbl), so that the tests check the model against an outside
// source. rd = x10, rs1 = x11, rs2 = x12. Returns 0 for a mnemonic it does not know.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace xpulp_asm {

constexpr int kRd = 10, kRs1 = 11, kRs2 = 12;

// `imm` is the instruction's immediate where it has one: the 6-bit .sci value (or lane index
// of pv.extract/insert), p.clip's Is2, the Is3 shift of the 16-bit MACs and p.addN, and for the
// bit-field immediate forms (Is3 << 5) | Is2.
uint32_t Assemble(std::string_view mnemonic, uint32_t imm = 0);

// True when the instruction takes an immediate instead of rs2.
bool TakesImmediate(std::string_view mnemonic);

// One row of xgap8_opcodes.txt.
struct OutsideRow {
  std::string mnemonic, operands;
  uint32_t match = 0, mask = 0;
  std::string extension;
};
const std::vector<OutsideRow>& OutsideTable();

}  // namespace xpulp_asm
