// The disassembler against GNU objdump (binutils-riscv64-unknown-elf, -M no-aliases): every
// instruction objdump decodes in the GAP8 kernels and the test programs must read the same in
// the model's disassembly, and have the decoder's op; the words objdump cannot decode (.4byte:
// the kernels' Xpulp) must be instructions of the model's tables.
#include <catch2/catch.hpp>
#include <regex>
#include <sstream>
#include <string>

#include "build_paths.hpp"
#include "gap8/decoded.h"
#include "gap8/disasm.h"
#include "run_program.hpp"

namespace {

struct Counts {
  int rv32imc = 0, xpulp = 0;
};

// objdump's operands without its comments: " <symbol+0x4>" after a target, "# 1c000ca0 <...>"
// after an address computation.
std::string WithoutComments(std::string operands) {
  if (const size_t hash = operands.find(" #"); hash != std::string::npos) operands.resize(hash);
  if (const size_t angle = operands.find(" <"); angle != std::string::npos) operands.resize(angle);
  return operands;
}

Counts CompareWithObjdump(const std::string& elf) {
  const pxflow::test::RunResult dump =
      pxflow::test::run_program(build_paths::gap8_objdump, {"-d", "-M", "no-aliases", elf});
  REQUIRE(dump.exit_code == 0);
  // "1c000086:\t00052283          \tlw\tt0,0(a0)"
  static const std::regex line(R"(^\s*([0-9a-f]+):\s+([0-9a-f]+)\s*\t([^\t]+)(?:\t(.*))?$)");
  Counts counts;
  std::istringstream in(dump.out);
  for (std::string text; std::getline(in, text);) {
    std::smatch m;
    if (!std::regex_match(text, m, line)) continue;
    const uint32_t pc = static_cast<uint32_t>(std::stoul(m[1], nullptr, 16));
    const uint32_t bits = static_cast<uint32_t>(std::stoul(m[2], nullptr, 16));
    const std::string mnemonic = m[3];
    const gap8::Disassembly ours = gap8::Disassemble(bits, pc);
    INFO(elf << " at " << m[1] << ": " << text);
    if (mnemonic == ".short") continue;  // padding
    if (mnemonic == ".4byte") {          // Xpulp, which objdump does not know
      CHECK(ours.known);
      counts.xpulp += ours.known;
      continue;
    }
    const std::string operands = m[4].matched ? WithoutComments(m[4]) : "";
    CHECK(ours.text == (operands.empty() ? mnemonic : mnemonic + " " + operands));
    CHECK(ours.op == gap8::Decode(bits).op);
    ++counts.rv32imc;
  }
  return counts;
}

}  // namespace

TEST_CASE("the disassembly of the GAP8 kernels is objdump's") {
  Counts total;
  for (const char* variant : {"original", "local", "global", "fast"}) {
    const Counts c = CompareWithObjdump(std::string(build_paths::gap8_kernel_dir) +
                                        "/pxflow_gap8_" + variant + ".elf");
    total.rv32imc += c.rv32imc;
    total.xpulp += c.xpulp;
  }
  CHECK(total.rv32imc > 5000);
  CHECK(total.xpulp > 20);
}

TEST_CASE("the disassembly of the test programs is objdump's") {
  int total = 0;
  for (const char* p : {"diff_compute", "diff_calls", "counters", "dma", "xpulp_isa", "hwloop"})
    total +=
        CompareWithObjdump(std::string(build_paths::gap8_program_dir) + "/" + p + ".elf").rv32imc;
  CHECK(total > 4000);
}
