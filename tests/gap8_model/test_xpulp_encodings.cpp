// The model's Xpulp table against GreenWaves' assembler (xgap8_opcodes.txt): every encoding
// the assembler emits for GAP8 is an instruction of the model, except the four the model leaves
// out on purpose (docs/gap8-model.md, "What is not modelled"), which stay illegal.
#include <catch2/catch.hpp>
#include <set>
#include <string>

#include "gap8/decoded.h"
#include "xpulp_asm.h"

TEST_CASE("every Xpulp encoding of GreenWaves' assembler decodes in the model") {
  const std::set<std::string> left_out = {"pv.vitop.max", "pv.vitop.sel", "pv.cplxmul.sc.s",
                                          "pv.cplxmul.sci.s"};
  int legal = 0, illegal = 0;
  for (const xpulp_asm::OutsideRow& r : xpulp_asm::OutsideTable()) {
    const bool expected = left_out.count(r.mnemonic) == 0;
    // The bare match (x0 everywhere, immediates 0) and the same with registers and an immediate
    // placed as the assembler would.
    for (const uint32_t word : {r.match, xpulp_asm::Assemble(r.mnemonic, 5)}) {
      if (word == 0) continue;  // the first row of a mnemonic is the one Assemble knows
      INFO(r.mnemonic << " " << r.operands << " insn 0x" << std::hex << word);
      const bool is_legal = gap8::Decode(word).op != gap8::Op::kIllegal;
      CHECK(is_legal == expected);
    }
    (expected ? legal : illegal) += 1;
  }
  CHECK(legal == 355);  // the whole table was read: 359 rows
  CHECK(illegal == 4);
}
