// gap8-run: runs a RISC-V ELF on the simulated GAP8 cluster and prints per-core counters.
//   gap8-run [--cores N] [--no-contention] [--max-cycles N] [--bench] prog.elf
// Exit status: the program's (0 / 1 when non-zero), 2 bad arguments or ELF, 3 illegal
// instruction, 4 memory fault, 5 cycle budget exceeded, 6 deadlock.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "gap8/cluster.h"
#include "gap8/elf_loader.h"

namespace {

struct Options {
  int cores = 8;
  bool contention = true;
  bool bench = false;
  uint64_t max_cycles = 4'000'000'000ull;
  std::string elf;
};

[[noreturn]] void Usage(const std::string& why) {
  std::fprintf(stderr,
               "gap8-run: %s (usage: gap8-run [--cores 1..8] [--no-contention] "
               "[--max-cycles N] [--bench] prog.elf)\n",
               why.c_str());
  std::exit(2);
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

uint64_t TotalInstructions(gap8::Cluster& cluster) {
  uint64_t n = 0;
  for (int i = 0; i < cluster.num_cores(); ++i) n += cluster.core(i).Totals()[GAP8_EVT_INSTR];
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  const Options opt = Parse(argc, argv);
  gap8::Cluster cluster({opt.cores, opt.contention, opt.max_cycles, {}});
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
