// Every arithmetic vector of the PULP project's Xpulp ISA tests (pulp-platform/riscv-tests,
// branch xpulp-dev), assembled from its mnemonic, decoded and executed by the model.
#include <catch2/catch.hpp>
#include <string>

#include "core_fixture.h"
#include "xpulp_asm.h"

namespace {

struct Vector {
  const char* mnemonic;
  uint32_t result, rs1, rs2_or_imm, rd_before;
};

constexpr Vector kVectors[] = {
#include "xpulp_riscv_tests_vectors.inc"
};

}  // namespace

TEST_CASE("riscv-tests xpulp-dev vectors: every one gives the test's result") {
  CoreFixture f;
  int checked = 0;
  for (const Vector& v : kVectors) {
    const bool imm = xpulp_asm::TakesImmediate(v.mnemonic);
    const uint32_t word = xpulp_asm::Assemble(v.mnemonic, imm ? v.rs2_or_imm : 0);
    INFO(v.mnemonic << " rs1 0x" << std::hex << v.rs1 << " op2 0x" << v.rs2_or_imm << " rd 0x"
                    << v.rd_before << " insn 0x" << word);
    REQUIRE(word != 0);
    CHECK(f.RunR(word, v.rs1, imm ? 0xDEADBEEFu : v.rs2_or_imm, v.rd_before) == v.result);
    ++checked;
  }
  CHECK(checked == 608);
}
