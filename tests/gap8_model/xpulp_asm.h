// A test-side assembler for PULPv2 mnemonics, written from the encoding tables (GVSOC
// isa_pulpv2.py, the RI5CY manual's encoding chapter), independently of the model's decoder
// tables: rd = x10, rs1 = x11, rs2 = x12. Returns 0 for a mnemonic it does not know.
#pragma once

#include <cstdint>
#include <string_view>

namespace xpulp_asm {

constexpr int kRd = 10, kRs1 = 11, kRs2 = 12;

// `imm` is the instruction's immediate where it has one: the 6-bit .sci value (or lane index
// of pv.extract/insert), p.clip's Is2, the Is3 shift of the 16-bit MACs and p.addN, and for the
// bit-field immediate forms (Is3 << 5) | Is2.
uint32_t Assemble(std::string_view mnemonic, uint32_t imm = 0);

// True when the instruction takes an immediate instead of rs2.
bool TakesImmediate(std::string_view mnemonic);

}  // namespace xpulp_asm
