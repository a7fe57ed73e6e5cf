// Differential test: the model's core against Unicorn (QEMU's RISC-V), compared after every
// instruction (pc and x1..x31) and on all of L1 and L2 at the end. Seeds are printed on failure;
// GAP8_DIFF_SEED=<n> reruns from another seed.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <memory>
#include <random>

#include "diff_runner.h"
#include "random_program.h"
#ifdef GAP8_HAVE_PROGRAMS
#include "program_runner.h"
#endif

namespace {

uint32_t BaseSeed() {
  const char* env = std::getenv("GAP8_DIFF_SEED");
  return env ? static_cast<uint32_t>(std::strtoul(env, nullptr, 0)) : 20261121u;
}

}  // namespace

TEST_CASE("random RV32IMC sequences (compressed included) match Unicorn step by step") {
  constexpr int kPrograms = 2000;
  constexpr int kLength = 120;
  const uint32_t base = BaseSeed();
  // One Unicorn serves kPerUnicorn sequences, each at its own address (Unicorn keeps the code
  // it translated); opening one per sequence would dominate the run time.
  constexpr int kPerUnicorn = 400;
  constexpr uint32_t kSlot = 8 * kLength;
  static_assert(kPerUnicorn * kSlot < GAP8_L2_SIZE);
  gap8::Memory memory;
  std::unique_ptr<UnicornCpu> uc;
  uint64_t steps = 0;
  for (int i = 0; i < kPrograms; ++i) {
    if (i % kPerUnicorn == 0) uc = std::make_unique<UnicornCpu>();
    const uint32_t seed = base + static_cast<uint32_t>(i);
    std::mt19937 rng(seed);
    const uint32_t code_base = GAP8_L2_BASE + (i % kPerUnicorn) * kSlot;
    const RandomProgram p = MakeRandomProgram(rng, kLength, code_base);
    memory.Write(kRandomDataBase, p.data.data(), kRandomDataSize);
    memory.Write(p.start, p.code.data(), static_cast<uint32_t>(p.code.size()));
    uint32_t regs[32];
    std::copy(p.regs.begin(), p.regs.end(), regs);
    const Regions regions = {{kRandomDataBase, kRandomDataSize},
                             {p.start, static_cast<uint32_t>(p.code.size())}};
    const DiffOutcome out =
        RunDifferential(*uc, memory, p.start, p.end, regs, 10 * kLength, regions);
    INFO("seed " << seed << " (GAP8_DIFF_SEED=" << seed << " reproduces it first)");
    REQUIRE(out.difference == "");
    steps += out.steps;
  }
  // Forward branches skip instructions, but most run: the sequences are not trivially short.
  CHECK(steps > kPrograms * kLength / 2);
}

TEST_CASE("encodings Unicorn refuses as illegal are illegal in the model too") {
  constexpr int kWords = 20000;  // 8 bytes each: all fit in L2, so one Unicorn serves them all
  std::mt19937 rng(BaseSeed());
  UnicornCpu uc;
  int refused = 0;
  for (int i = 0; i < kWords; ++i) {
    uint32_t word = rng();
    if (i % 2 == 0) {  // a compressed parcel, followed by zeros
      word &= 0xFFFFu;
      if ((word & 3u) == 3u) word &= ~1u;
    }
    const gap8::Decoded d = gap8::Decode(word);
    if (gap8::IsXpulp(d.op)) continue;  // encodings QEMU does not know: expected to differ
    const uint32_t addr = GAP8_L2_BASE + 8u * static_cast<uint32_t>(i);
    uc.Write(addr, &word, 4);
    uc.set_pc(addr);
    for (int r = 1; r < 32; ++r) uc.set_reg(r, GAP8_L1_BASE + 0x8000);
    int calls = 0;
    const std::string error = uc.Run(addr + 8, [&](uint32_t) { return ++calls == 1; });
    if (error.find("UC_ERR_EXCEPTION") == std::string::npos &&
        error.find("UC_ERR_INSN_INVALID") == std::string::npos)
      continue;
    ++refused;
    INFO("word " << gap8::Hex(word) << " refused by Unicorn: " << error);
    REQUIRE(d.op == gap8::Op::kIllegal);
  }
  CHECK(refused > 1000);  // the sample does reach the illegal space
}

#ifdef GAP8_HAVE_PROGRAMS
TEST_CASE("compiled C programs match Unicorn step by step up to the exit") {
  for (const char* name : {"diff_compute", "diff_calls"}) {
    gap8::Memory memory;
    UnicornCpu uc;
    const gap8::ElfImage image = gap8::LoadElf(ProgramPath(name), memory);
    const uint32_t exit_pc = image.symbols.at("__gap8_exit");
    const uint32_t regs[32] = {};
    const DiffOutcome out =
        RunDifferential(uc, memory, image.entry, exit_pc, regs, 5'000'000, WholeMemory());
    INFO(name << ": " << out.steps << " instructions");
    REQUIRE(out.difference == "");
    CHECK(out.steps > 1000);
  }
}
#endif
