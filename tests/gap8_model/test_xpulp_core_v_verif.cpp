// The Xpulp vectors of OpenHW Group's core-v-verif (xpulp_core_v_verif_vectors.inc: values its
// authors wrote for RI5CY's successor, the CV32E40P), assembled from GreenWaves' assembler table
// (xgap8_opcodes.txt, never the model's own xpulp.tbl) into one program that the model runs in
// the four modes of the outside-suite runs: 1 core; 8 cores with core 0 alone running it; 8
// cores all running it; and without compressed instructions. With RVC, a c.nop before every
// tested instruction puts every other one at a pc 2 mod 4. Each core writes its results to its
// own slots in L2; the host compares them all.
#include <catch2/catch.hpp>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "core_fixture.h"
#include "gap8/cluster.h"
#include "xpulp_asm.h"

namespace {

struct AluRow {
  const char* mnemonic;
  uint32_t imm, rs1, rs2, rd_before, result, mask;
  const char* source;
};
struct BranchRow {
  const char* mnemonic;
  int32_t imm;
  uint32_t rs1;
  bool taken;
  const char* source;
};
struct MemRow {
  const char* form;
  uint32_t offset, low, word, data, result;
  const char* source;
};

#define CVV_ALU(...) AluRow{__VA_ARGS__},
#define CVV_BRANCH(...)
#define CVV_MEM(...)
const std::vector<AluRow> kAlu = {
#include "xpulp_core_v_verif_vectors.inc"
};
#undef CVV_ALU
#undef CVV_BRANCH
#define CVV_ALU(...)
#define CVV_BRANCH(...) BranchRow{__VA_ARGS__},
const std::vector<BranchRow> kBranch = {
#include "xpulp_core_v_verif_vectors.inc"
};
#undef CVV_BRANCH
#undef CVV_MEM
#define CVV_BRANCH(...)
#define CVV_MEM(...) MemRow{__VA_ARGS__},
const std::vector<MemRow> kMem = {
#include "xpulp_core_v_verif_vectors.inc"
};
#undef CVV_ALU
#undef CVV_BRANCH
#undef CVV_MEM

// RV32I encodings for the program's scaffolding (standard RISC-V, not Xpulp).
constexpr uint32_t kOpImm = 0x13, kLoad = 0x03, kStore = 0x23, kOp = 0x33, kLui = 0x37;
uint32_t Lui(uint32_t rd, uint32_t v) { return (v & 0xFFFFF000u) | (rd << 7) | kLui; }
uint32_t Addi(uint32_t rd, uint32_t rs1, int32_t imm) { return EncodeI(kOpImm, 0, rd, rs1, imm); }
uint32_t Lw(uint32_t rd, uint32_t rs1, int32_t imm) { return EncodeI(kLoad, 2, rd, rs1, imm); }
uint32_t Sw(uint32_t rs2, uint32_t rs1, int32_t imm) {
  const auto u = static_cast<uint32_t>(imm);
  return ((u >> 5 & 0x7Fu) << 25) | (rs2 << 20) | (rs1 << 15) | (2u << 12) | ((u & 31u) << 7) |
         kStore;
}
uint32_t Branch(uint32_t f3, uint32_t rs1, uint32_t rs2, int32_t off) {
  const auto u = static_cast<uint32_t>(off);
  return ((u >> 12 & 1u) << 31) | ((u >> 5 & 0x3Fu) << 25) | (rs2 << 20) | (rs1 << 15) |
         (f3 << 12) | ((u >> 1 & 15u) << 8) | ((u >> 11 & 1u) << 7) | 0x63;
}

// Where a load/store form's operands go, from its binutils operand syntax in GreenWaves' table:
// loads d,o(s!) / d,t(s!) / d,t(s); stores t,q(s!) / t,d(s!) / t,d(s). rd x10, base x11, x12.
uint32_t AssembleMem(std::string_view form, uint32_t offset) {
  const std::string name(form.substr(0, form.find('.', 2)));
  const bool reg = form.find(".rr") != std::string_view::npos;
  const bool post = form.find("post") != std::string_view::npos;
  const bool store = name[2] == 's';
  const std::string ops = std::string(store ? "t," : "d,") +
                          (reg ? (store ? "d" : "t") : (store ? "q" : "o")) +
                          (post ? "(s!)" : "(s)");
  for (const xpulp_asm::OutsideRow& r : xpulp_asm::OutsideTable()) {
    if (r.mnemonic != name || r.operands != ops) continue;
    uint32_t w = r.match | (11u << 15);
    if (store) {
      w |= 12u << 20;
      if (reg)
        w |= 10u << 7;
      else
        w |= ((offset >> 5 & 0x7Fu) << 25) | ((offset & 31u) << 7);
    } else {
      w |= 10u << 7;
      w |= reg ? 12u << 20 : (offset & 0xFFFu) << 20;
    }
    return w;
  }
  return 0;
}

enum class Mode { kOneCore, kCore0Of8, kAllOf8, kNoRvc };
constexpr uint32_t kResults = GAP8_L2_BASE + 0x40000, kScratch = GAP8_L2_BASE + 0x70000;
constexpr uint32_t kScratchStride = 0x1000;  // per core; 8 bytes a memory row

class Program {
 public:
  explicit Program(bool rvc) : rvc_(rvc) {}
  void Word(uint32_t w) {
    bytes_.insert(bytes_.end(), {uint8_t(w), uint8_t(w >> 8), uint8_t(w >> 16), uint8_t(w >> 24)});
  }
  void Li(uint32_t rd, uint32_t v) {
    const uint32_t hi = (v + 0x800u) & 0xFFFFF000u;
    Word(Lui(rd, hi));
    Word(Addi(rd, rd, static_cast<int32_t>(v - hi)));
  }
  void Tested(uint32_t w) {  // the instruction under test, after a c.nop with RVC
    if (rvc_) bytes_.insert(bytes_.end(), {0x01, 0x00});
    Word(w);
  }
  void Result(uint32_t rs) {  // x5: this core's next result slot
    Word(Sw(rs, 5, 0));
    Word(Addi(5, 5, 4));
  }
  // Sleeps for good on the dispatch FIFO (nothing is pushed): 4 words.
  void Sleep() {
    Li(7, GAP8_EU_DISPATCH_FIFO);
    Word(Lw(9, 7, 0));
  }
  size_t size() const { return bytes_.size(); }
  const std::vector<uint8_t>& bytes() const { return bytes_; }

 private:
  bool rvc_;
  std::vector<uint8_t> bytes_;
};

uint32_t ResultSlots() {
  return static_cast<uint32_t>(kAlu.size() + kBranch.size() + 2 * kMem.size());
}
uint32_t RowAddress(int core, size_t i, const MemRow& r) {
  return kScratch + kScratchStride * static_cast<uint32_t>(core) + 8 * static_cast<uint32_t>(i) +
         r.low;
}

std::vector<uint8_t> Build(Mode mode) {
  Program p(mode != Mode::kNoRvc);
  p.Word(0xF1402473u);  // csrr x8, mhartid
  if (mode == Mode::kCore0Of8) {
    p.Word(Branch(0, 8, 0, 16));  // core 0 goes on; the others sleep
    p.Sleep();
  }
  p.Li(9, ResultSlots() * 4);
  p.Word(EncodeR(kOp, 0, 1, 9, 8, 9));  // mul x9, x8, x9
  p.Li(5, kResults);
  p.Word(EncodeR(kOp, 0, 0, 5, 5, 9));  // add x5, x5, x9
  p.Li(9, kScratchStride);
  p.Word(EncodeR(kOp, 0, 1, 9, 8, 9));
  p.Li(6, kScratch);
  p.Word(EncodeR(kOp, 0, 0, 6, 6, 9));  // x6: this core's memory rows
  for (const AluRow& r : kAlu) {
    p.Li(11, r.rs1);
    p.Li(12, r.rs2);
    p.Li(10, r.rd_before);
    p.Tested(xpulp_asm::Assemble(r.mnemonic, r.imm));
    p.Result(10);
  }
  for (const BranchRow& r : kBranch) {  // taken: skips the addi, x10 stays 2
    p.Li(11, r.rs1);
    p.Word(Addi(10, 0, 2));
    p.Tested(xpulp_asm::Assemble(r.mnemonic, 0) | ((static_cast<uint32_t>(r.imm) & 31u) << 20) |
             (8u << 7));
    p.Word(Addi(10, 0, 1));
    p.Result(10);
  }
  for (const MemRow& r : kMem) {
    const bool store = r.form[2] == 's',
               reg = std::string_view(r.form).find(".rr") != std::string_view::npos;
    const bool post = std::string_view(r.form).find("post") != std::string_view::npos;
    const uint32_t off_reg = store ? 10 : 12;
    p.Word(Addi(11, 6, static_cast<int32_t>(r.low)));  // the address
    if (reg) p.Li(off_reg, r.offset);
    if (reg && !post) p.Word(EncodeR(kOp, 0, 0x20, 11, 11, off_reg));  // base = address - offset
    if (store) p.Li(12, r.data);
    p.Tested(AssembleMem(r.form, r.offset));
    p.Result(10);
    p.Result(11);
    p.Word(Addi(6, 6, 8));
  }
  if (mode == Mode::kAllOf8) {
    p.Li(7, GAP8_EU_BARRIER_WAIT);
    p.Word(Lw(9, 7, 0));
    p.Word(Branch(0, 8, 0, 20));  // core 0 ends the run once every core has arrived
    p.Sleep();
    p.Word(0x0000006Fu);  // j .
  }
  p.Li(7, GAP8_CTRL_EXIT);
  p.Word(Sw(0, 7, 0));
  p.Word(0x0000006Fu);
  return p.bytes();
}

// The bytes a memory row's address holds before the run: the word a load reads, or for a store
// the result with the bytes the store must write inverted (so an unwritten byte is caught).
uint32_t Before(const MemRow& r) {
  if (r.form[2] != 's') return r.word;
  const int n = r.form[3] == 'b' ? 1 : r.form[3] == 'h' ? 2 : 4;
  return r.result ^ (n == 4 ? 0xFFFFFFFFu : (1u << (8 * n)) - 1u);
}

std::string Name(Mode m) {
  switch (m) {
    case Mode::kOneCore:
      return "1 core";
    case Mode::kCore0Of8:
      return "8 cores, core 0";
    case Mode::kAllOf8:
      return "8 cores, all";
    case Mode::kNoRvc:
      return "1 core, no RVC";
  }
  return "";
}

void RunMode(Mode mode) {
  const bool eight = mode == Mode::kCore0Of8 || mode == Mode::kAllOf8;
  gap8::ClusterConfig config;
  config.cores = eight ? 8 : 1;
  config.max_cycles = 50'000'000;
  gap8::Cluster cluster(config);
  const std::vector<uint8_t> code = Build(mode);
  REQUIRE(code.size() < kResults - GAP8_L2_BASE);
  REQUIRE(cluster.memory().Write(GAP8_L2_BASE, code.data(), static_cast<uint32_t>(code.size())));
  const int running = mode == Mode::kAllOf8 ? 8 : 1;
  for (int c = 0; c < running; ++c)
    for (size_t i = 0; i < kMem.size(); ++i) {
      const uint32_t before = Before(kMem[i]);
      REQUIRE(cluster.memory().Write(RowAddress(c, i, kMem[i]), &before, 4));
    }
  cluster.Start(GAP8_L2_BASE);
  const gap8::RunResult run = cluster.Run();
  INFO(Name(mode));
  REQUIRE_FALSE(run.fault.has_value());
  int failed = 0, checked = 0;
  auto check = [&](int core, uint32_t got, uint32_t want, uint32_t mask, const char* what,
                   const char* source) {
    ++checked;
    if ((got & mask) == (want & mask)) return;
    ++failed;
    FAIL_CHECK(Name(mode) << " core " << core << ": " << what << " (core-v-verif " << source
                          << "): got 0x" << std::hex << got << ", want 0x" << want << " mask 0x"
                          << mask);
  };
  for (int c = 0; c < running; ++c) {
    std::vector<uint32_t> got(ResultSlots());
    REQUIRE(cluster.memory().Read(kResults + 4 * ResultSlots() * static_cast<uint32_t>(c),
                                  got.data(), 4 * ResultSlots()));
    size_t k = 0;
    for (const AluRow& r : kAlu) check(c, got[k++], r.result, r.mask, r.mnemonic, r.source);
    for (const BranchRow& r : kBranch)
      check(c, got[k++], r.taken ? 2 : 1, ~0u, r.mnemonic, r.source);
    for (size_t i = 0; i < kMem.size(); ++i) {
      const MemRow& r = kMem[i];
      const uint32_t addr = RowAddress(c, i, r);
      const bool store = r.form[2] == 's',
                 post = std::string_view(r.form).find("post") != std::string_view::npos;
      const bool reg = std::string_view(r.form).find(".rr") != std::string_view::npos;
      if (store) {
        uint32_t word = 0;
        REQUIRE(cluster.memory().Read(addr, &word, 4));
        check(c, word, r.result, ~0u, r.form, r.source);
        ++k;
      } else {
        check(c, got[k++], r.result, ~0u, r.form, r.source);
      }
      const uint32_t base_after = post ? addr + r.offset : reg ? addr - r.offset : addr;
      check(c, got[k++], base_after, ~0u, r.form, r.source);
    }
  }
  INFO(failed << " of " << checked << " failed");
  CHECK(failed == 0);
  CHECK(checked == running * static_cast<int>(ResultSlots()));
}

// ---- Hardware loops: pulp-platform/riscv-tests isa/rv32uxpulphwloop/hwloop.S ----
// (commit 952183959caf3b680ee8368945dca4066c48243a): tests 2, 3 and 4, the documentation's nested
// loop written with lp.counti/lp.endi/lp.starti, lp.setup and lp.setupi, each asserting a0 =
// 300 and a1 = 40 afterwards; plus test 2 with the outer count from a register (lp.count), which
// the RI5CY manual defines as lp.counti's count taken from rs1. The match of each lp.* comes from
// GreenWaves' table; the operand fields from the RI5CY manual's hardware-loop encoding table: L
// in bit 7, uimmL in bits 31..20 (lp.starti/endi/setup: an offset in half-words from the pc;
// lp.counti/setupi: the count), lp.setupi's end offset uimmS in bits 19..15, rs1 in 19..15.
uint32_t LoopMatch(std::string_view mnemonic) {
  for (const xpulp_asm::OutsideRow& r : xpulp_asm::OutsideTable())
    if (r.mnemonic == mnemonic) return r.match;
  return 0;
}
uint32_t Loop(std::string_view mnemonic, uint32_t l, uint32_t uimm_l, uint32_t rs1_or_uimm_s = 0) {
  return LoopMatch(mnemonic) | (uimm_l << 20) | (rs1_or_uimm_s << 15) | (l << 7);
}

enum class Outer { kCounti, kCount, kSetup, kSetupSetupi };
constexpr uint32_t kA0 = 10, kA1 = 11, kA3 = 13;

// One of hwloop.S's nested loops; leaves a0 and a1 in this core's next two result slots.
void NestedLoop(Program& p, Outer outer) {
  p.Li(kA0, 0);
  p.Li(kA1, 0);
  p.Li(kA3, 10);
  // Layout from the first loop instruction: the outer set-up (3 words, or 1 with lp.setup), the
  // inner set-up (3 words, or 1 with lp.setupi), 3 inner body words, 2 outer body words.
  const uint32_t outer_words = outer == Outer::kCounti || outer == Outer::kCount ? 3 : 1;
  const uint32_t inner_words = outer == Outer::kSetupSetupi ? 1 : 3;
  const uint32_t end_inner = 4 * (outer_words + inner_words + 2);  // from the first instruction
  const uint32_t end_outer = end_inner + 8;
  const uint32_t top_outer = 4 * outer_words;
  if (outer_words == 3) {
    p.Word(outer == Outer::kCounti ? Loop("lp.counti", 1, 10) : Loop("lp.count", 1, 0, kA3));
    p.Word(Loop("lp.endi", 1, (end_outer - 4) / 2));
    p.Word(Loop("lp.starti", 1, (top_outer - 8) / 2));
  } else {
    p.Word(Loop("lp.setup", 1, end_outer / 2, kA3));
  }
  const uint32_t here = top_outer;  // the inner set-up's first word
  if (inner_words == 3) {
    p.Word(Loop("lp.counti", 0, 10));
    p.Word(Loop("lp.endi", 0, (end_inner - here - 4) / 2));
    p.Word(Loop("lp.starti", 0, (here + 12 - here - 8) / 2));
  } else {
    p.Word(Loop("lp.setupi", 0, 10, (end_inner - here) / 2));
  }
  p.Word(Addi(kA0, kA0, 1));
  p.Word(Addi(kA0, kA0, 1));
  p.Word(Addi(kA0, kA0, 1));  // the inner loop's last instruction
  p.Word(Addi(kA1, kA1, 2));
  p.Word(Addi(kA1, kA1, 2));  // the outer loop's last instruction
  p.Result(kA0);
  p.Result(kA1);
}

constexpr Outer kOuters[] = {Outer::kCounti, Outer::kSetup, Outer::kSetupSetupi, Outer::kCount};
const char* const kLoopSources[] = {"hwloop.S test_2 (lp.counti, lp.endi, lp.starti)",
                                    "hwloop.S test_3 (lp.setup)", "hwloop.S test_4 (lp.setupi)",
                                    "hwloop.S test_2 with lp.count"};

void RunLoops(Mode mode) {
  const bool eight = mode == Mode::kCore0Of8 || mode == Mode::kAllOf8;
  Program p(mode != Mode::kNoRvc);
  p.Word(0xF1402473u);  // csrr x8, mhartid
  if (mode == Mode::kCore0Of8) {
    p.Word(Branch(0, 8, 0, 16));
    p.Sleep();
  }
  p.Word(Addi(9, 0, 64));
  p.Word(EncodeR(kOp, 0, 1, 9, 8, 9));  // x5: kResults + 64 * core
  p.Li(5, kResults);
  p.Word(EncodeR(kOp, 0, 0, 5, 5, 9));
  for (const Outer o : kOuters) {
    if (mode != Mode::kNoRvc) p.Word(0x00010001u);  // two c.nop: compressed code, loops aligned
    NestedLoop(p, o);
  }
  if (mode == Mode::kAllOf8) {
    p.Li(7, GAP8_EU_BARRIER_WAIT);
    p.Word(Lw(9, 7, 0));
    p.Word(Branch(0, 8, 0, 20));
    p.Sleep();
    p.Word(0x0000006Fu);
  }
  p.Li(7, GAP8_CTRL_EXIT);
  p.Word(Sw(0, 7, 0));
  p.Word(0x0000006Fu);

  gap8::ClusterConfig config;
  config.cores = eight ? 8 : 1;
  config.max_cycles = 10'000'000;
  gap8::Cluster cluster(config);
  REQUIRE(cluster.memory().Write(GAP8_L2_BASE, p.bytes().data(), static_cast<uint32_t>(p.size())));
  cluster.Start(GAP8_L2_BASE);
  const gap8::RunResult run = cluster.Run();
  INFO(Name(mode));
  REQUIRE_FALSE(run.fault.has_value());
  for (int c = 0; c < (mode == Mode::kAllOf8 ? 8 : 1); ++c) {
    uint32_t got[8] = {};
    REQUIRE(cluster.memory().Read(kResults + 64 * static_cast<uint32_t>(c), got, sizeof got));
    for (int t = 0; t < 4; ++t) {
      INFO("core " << c << ": " << kLoopSources[t]);
      CHECK(got[2 * t] == 300u);
      CHECK(got[2 * t + 1] == 40u);
    }
  }
}

}  // namespace

TEST_CASE("core-v-verif vectors: the row counts the docs give") {
  CHECK(kAlu.size() == 1656);
  CHECK(kBranch.size() == 12);
  CHECK(kMem.size() == 144);
}

TEST_CASE("core-v-verif vectors: every form assembles from GreenWaves' table") {
  for (const AluRow& r : kAlu) {
    INFO(r.mnemonic << " " << r.source);
    CHECK(xpulp_asm::Assemble(r.mnemonic, r.imm) != 0);
  }
  for (const BranchRow& r : kBranch) CHECK(xpulp_asm::Assemble(r.mnemonic, 0) != 0);
  for (const MemRow& r : kMem) {
    INFO(r.form << " " << r.source);
    CHECK(AssembleMem(r.form, r.offset) != 0);
  }
}

TEST_CASE("core-v-verif vectors: 1 core") { RunMode(Mode::kOneCore); }
TEST_CASE("core-v-verif vectors: 8 cores, core 0 alone") { RunMode(Mode::kCore0Of8); }
TEST_CASE("core-v-verif vectors: 8 cores, all") { RunMode(Mode::kAllOf8); }
TEST_CASE("core-v-verif vectors: 1 core, no RVC") { RunMode(Mode::kNoRvc); }

TEST_CASE("riscv-tests hwloop.S loops: 1 core") { RunLoops(Mode::kOneCore); }
TEST_CASE("riscv-tests hwloop.S loops: 8 cores, core 0 alone") { RunLoops(Mode::kCore0Of8); }
TEST_CASE("riscv-tests hwloop.S loops: 8 cores, all") { RunLoops(Mode::kAllOf8); }
TEST_CASE("riscv-tests hwloop.S loops: 1 core, no RVC") { RunLoops(Mode::kNoRvc); }
