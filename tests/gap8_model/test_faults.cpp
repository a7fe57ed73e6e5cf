// Every fault kind ends the run with one message naming core, pc and instruction.
#include <catch2/catch.hpp>

#include "build_paths.hpp"
#include "program_runner.h"

namespace {

gap8::Fault ExpectFault(const std::string& name, RunOptions options, gap8::FaultKind kind) {
  ProgramRun run = RunProgram(name, options);
  INFO(run.Describe());
  REQUIRE(run.result.fault);
  CHECK(run.result.fault->kind == kind);
  CHECK_THAT(run.result.fault->Message(),
             Catch::Matchers::Matches(
                 "core [0-7] at pc 0x1c[0-9a-f]{6} \\(insn 0x[0-9a-f]{8}: [a-z].*\\): .+"));
  return *run.result.fault;
}

}  // namespace

TEST_CASE("illegal instruction") {
  const gap8::Fault f =
      ExpectFault("fault_illegal", OnCores(1), gap8::FaultKind::kIllegalInstruction);
  CHECK(f.insn == 0);
  CHECK(f.what == "illegal instruction");
}

TEST_CASE("hardware loop whose last instruction is a branch") {
  const gap8::Fault f = ExpectFault("fault_hwloop", OnCores(1), gap8::FaultKind::kHardwareLoop);
  CHECK((f.insn & 0x7F) == 0x63);  // the branch itself
  CHECK(f.what ==
        "the last instruction of a hardware loop must not be a branch (RI5CY manual, hardware "
        "loops)");
}

TEST_CASE("load from unmapped memory") {
  const gap8::Fault f = ExpectFault("fault_unmapped", OnCores(2), gap8::FaultKind::kMemory);
  CHECK(f.what == "load of 4 bytes from unmapped address 0x30000000");
}

TEST_CASE("runaway program stops at the cycle budget") {
  RunOptions options = OnCores(1);
  options.max_cycles = 50'000;
  const gap8::Fault f = ExpectFault("fault_runaway", options, gap8::FaultKind::kCycleBudget);
  CHECK(f.what == "cycle budget of 50000 cycles exceeded");
}

TEST_CASE("barrier that never completes is a deadlock, on 2..8 cores") {
  for (int cores = 2; cores <= 8; ++cores) {
    const gap8::Fault f = ExpectFault("fault_deadlock", OnCores(cores), gap8::FaultKind::kDeadlock);
    CHECK(f.core == 0);
    CHECK(f.what ==
          "barrier never completes: 1 of " + std::to_string(cores) + " team cores arrived");
  }
}

TEST_CASE("a barrier of a one-core team passes") {
  ProgramRun run = RunProgram("fault_deadlock", OnCores(1));
  CHECK(run.ok());
}

TEST_CASE("waiting for the DMA event with no transfer in flight is a deadlock") {
  const gap8::Fault f = ExpectFault("fault_dma_wait", OnCores(4), gap8::FaultKind::kDeadlock);
  CHECK(f.core == 0);
  CHECK(f.what == "waits for an event (mask 0x00000100) that nothing will raise");
}

TEST_CASE("a 17th DMA counter, and a size beyond mchan's 16 bits, are memory faults") {
  gap8::Fault f = ExpectFault("fault_dma_counters", OnCores(1), gap8::FaultKind::kMemory);
  CHECK(f.what == "DMA: all 16 counters are allocated (transfers never freed)");
  RunOptions big = OnCores(1);
  big.before_run = [](gap8::Cluster& cluster, const gap8::ElfImage& image) {
    const uint32_t mode = 1;
    cluster.memory().Write(image.symbols.at("dma_fault_mode"), &mode, 4);
  };
  f = ExpectFault("fault_dma_counters", big, gap8::FaultKind::kMemory);
  CHECK(f.what == "DMA transfer of 0 bytes (mchan sizes are 1..65535)");
}

TEST_CASE("a DMA transfer outside L1 is a memory fault at the push") {
  const gap8::Fault f = ExpectFault("fault_dma_range", OnCores(1), gap8::FaultKind::kMemory);
  CHECK(f.what.find("outside L1") != std::string::npos);
}

TEST_CASE("a missing or malformed ELF is an ElfError, not a crash") {
  gap8::Memory memory;
  CHECK_THROWS_AS(gap8::LoadElf("/nonexistent.elf", memory), gap8::ElfError);
  CHECK_THROWS_AS(gap8::LoadElf(build_paths::gap8_program_dir, memory), gap8::ElfError);
  CHECK_THROWS_WITH(gap8::LoadElf(ProgramPath("elf_outside"), memory),
                    Catch::Matchers::Contains("segment at 0x1ffff000") &&
                        Catch::Matchers::Contains("is outside L1 and L2"));
}
