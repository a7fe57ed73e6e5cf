// gap8-run: runs a RISC-V ELF on the simulated GAP8 cluster and prints per-core counters.
//   gap8-run [--cores N] [--no-contention] [--max-cycles N] [--bench] [--trace] prog.elf
// --trace: one line per executed instruction on stderr (cycle, core, pc, bits, assembly).
// Exit status: the program's (0 / 1 when non-zero), 2 bad arguments or ELF, 3 illegal
// instruction, 4 memory fault, 5 cycle budget exceeded, 6 deadlock, 7 hardware loop rule.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "gap8/cluster.h"
#include "gap8/disasm.h"
#include "gap8/elf_loader.h"

namespace {

struct Options {
  int cores = 8;
  bool contention = true;
  bool bench = false;
  bool trace = false;
  uint64_t max_cycles = 4'000'000'000ull;
  std::string elf;
};

constexpr const char* kUsage =
    "usage: gap8-run [--cores 1..8] [--no-contention] [--max-cycles N] [--bench] [--trace] "
    "prog.elf";

[[noreturn]] void Usage(const std::string& why) {
  std::fprintf(stderr, "gap8-run: %s (%s)\n", why.c_str(), kUsage);
  std::exit(2);
}

[[noreturn]] void Help() {
  std::printf(
      "%s\n"
      "Runs a RISC-V ELF on the simulated GAP8 cluster and prints per-core counters.\n"
      "  --cores N        cluster cores, 1..8 (default 8)\n"
      "  --no-contention  no TCDM bank conflicts\n"
      "  --max-cycles N   cycle budget (default 4e9)\n"
      "  --bench          also print simulated instructions per host second\n"
      "  --trace          one line per executed instruction on stderr: the cycle it issues\n"
      "                   at (before its fetch wait), core, pc, bits and assembly, e.g.\n"
      "                   cycle 220 core 0 pc 0x1c000356 insn 0x0016c58b p.lbu a1,1(a3!)\n"
      "Exit status: the program's (0, or 1 for non-zero), 2 bad arguments or ELF, 3 illegal\n"
      "instruction, 4 memory fault, 5 cycle budget, 6 deadlock, 7 hardware loop rule.\n",
      kUsage);
  std::exit(0);
}

uint64_t ParseNumber(const char* text, const char* flag) {
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text, &end, 0);
  if (!text[0] || *end || text[0] == '-') Usage(std::string("bad value for ") + flag);
  return v;
}

Options Parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--cores" && has_value) {
      const uint64_t n = ParseNumber(argv[++i], "--cores");
      if (n < 1 || n > 8) Usage("--cores must be 1..8");
      o.cores = static_cast<int>(n);
    } else if (a == "--max-cycles" && has_value) {
      o.max_cycles = ParseNumber(argv[++i], "--max-cycles");
    } else if (a == "--no-contention") {
      o.contention = false;
    } else if (a == "--bench") {
      o.bench = true;
    } else if (a == "--trace") {
      o.trace = true;
    } else if (a == "--help" || a == "-h") {
      Help();
    } else if (!a.empty() && a[0] == '-') {
      Usage("unknown or incomplete option " + a);
    } else if (o.elf.empty()) {
      o.elf = a;
    } else {
      Usage("more than one ELF given");
    }
  }
  if (o.elf.empty()) Usage("no ELF given");
  return o;
}

int FaultStatus(gap8::FaultKind kind) {
  switch (kind) {
    case gap8::FaultKind::kIllegalInstruction:
      return 3;
    case gap8::FaultKind::kMemory:
      return 4;
    case gap8::FaultKind::kCycleBudget:
      return 5;
    case gap8::FaultKind::kDeadlock:
      return 6;
    case gap8::FaultKind::kHardwareLoop:
      return 7;
  }
  return 4;
}

void PrintCounters(gap8::Cluster& cluster) {
  static const char* kNames[] = {"active", "instr",      "ld_stall",   "jr_stall",
                                 "imiss",  "ld",         "st",         "jump",
                                 "branch", "btaken",     "rvc",        "ld_ext",
                                 "st_ext", "ld_ext_cyc", "st_ext_cyc", "tcdm_cont"};
  std::printf("core %10s", "cycles");
  for (const char* n : kNames) std::printf(" %10s", n);
  std::printf("\n");
  for (int i = 0; i < cluster.num_cores(); ++i) {
    const gap8::EventTotals t = cluster.core(i).Totals();
    std::printf("%4d %10llu", i, static_cast<unsigned long long>(t[GAP8_EVT_CYCLES]));
    for (int e = 0; e <= GAP8_EVT_TCDM_CONT; ++e)
      std::printf(" %10llu", static_cast<unsigned long long>(t[e]));
    std::printf("\n");
  }
}

// --trace's line: "cycle 1204 core 3 pc 0x1c000104 insn 0x0005a503 lw a0,0(a1)".
void TraceLine(int core, uint64_t cycle, uint32_t pc, uint32_t bits) {
  const bool rvc = gap8::IsCompressed(bits & 0xFFFFu);
  std::fprintf(stderr,
               rvc ? "cycle %llu core %d pc 0x%08x insn     0x%04x %s\n"
                   : "cycle %llu core %d pc 0x%08x insn 0x%08x %s\n",
               static_cast<unsigned long long>(cycle), core, pc, bits,
               gap8::DisassembleText(bits, pc).c_str());
}

uint64_t TotalInstructions(gap8::Cluster& cluster) {
  uint64_t n = 0;
  for (int i = 0; i < cluster.num_cores(); ++i) n += cluster.core(i).Totals()[GAP8_EVT_INSTR];
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  const Options opt = Parse(argc, argv);
  gap8::ClusterConfig config{opt.cores, opt.contention, opt.max_cycles, {}, {}};
  if (opt.trace) config.trace = TraceLine;
  gap8::Cluster cluster(config);
  gap8::ElfImage image;
  try {
    image = gap8::LoadElf(opt.elf, cluster.memory());
  } catch (const std::exception& e) {  // ElfError, or no memory for a corrupt file's segment
    std::fprintf(stderr, "gap8-run: %s\n", e.what());
    return 2;
  }
  cluster.Start(image.entry);
  const auto t0 = std::chrono::steady_clock::now();
  const gap8::RunResult r = cluster.Run();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::fflush(stdout);
  if (r.fault) {
    std::fprintf(stderr, "gap8-run: %s: %s\n", gap8::FaultKindName(r.fault->kind),
                 r.fault->Message().c_str());
    return FaultStatus(r.fault->kind);
  }
  std::printf("gap8-run: exit %d after %llu cycles (%d cores, TCDM contention %s)\n", r.exit_code,
              static_cast<unsigned long long>(r.cycles), opt.cores, opt.contention ? "on" : "off");
  PrintCounters(cluster);
  if (opt.bench) {
    const uint64_t n = TotalInstructions(cluster);
    std::printf("gap8-run: bench: %llu instructions in %.3f s host wall clock = %.1f M instr/s\n",
                static_cast<unsigned long long>(n), seconds, n / seconds / 1e6);
  }
  return r.exit_code == 0 ? 0 : 1;
}
