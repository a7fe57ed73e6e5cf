#include "psadbw_ceiling.hpp"

#include <x86intrin.h>

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "isa_mask.hpp"
#include "isa_table.hpp"

namespace pxflow::cpu {
namespace {

// Whether the ISA whose table row unlocks this width (its `ceiling` column; the width's file is
// compiled with that row's flags) can run here and is not masked.
bool may_use(std::string_view width) {
  for (const IsaInfo& isa : isa_table())
    if (isa.compiled() && width == isa.ceiling) return isa_unavailable(isa.name).empty();
  return false;
}

// Every SAD instruction a kernel of the table may search with; `bytes`: bytes compared (absolute
// differences summed) per instruction.
struct Instruction {
  const char* name;
  const char* width;
  int bytes;
  std::uint64_t (*run)(const std::uint8_t*, std::int64_t);
};
constexpr Instruction kInstructions[] = {{"psadbw xmm", "xmm", 16, psadbw_xmm},
                                         {"psadbw ymm", "ymm", 32, psadbw_ymm},
                                         {"vmpsadbw ymm", "ymm", 64, vmpsadbw_ymm},
                                         {"psadbw zmm", "zmm", 64, psadbw_zmm},
                                         {"vdbpsadbw zmm", "zmm", 128, vdbpsadbw_zmm}};

std::vector<const Instruction*> usable() {
  std::vector<const Instruction*> out;
  for (const Instruction& i : kInstructions)
    if (may_use(i.width)) out.push_back(&i);
  return out;
}

// One thread's fastest trial while `stop` is not set; sets it when its trials are done, so that
// no thread's later trials run alone on a core another thread has left.
double fastest_trial(const Instruction& w, std::atomic<bool>& stop) {
  alignas(64) std::uint8_t data[768];
  for (int i = 0; i < 768; ++i) data[i] = static_cast<std::uint8_t>(i * 37);
  constexpr std::int64_t kRounds = 20'000;
  volatile std::uint64_t sink = w.run(data, 100 * kRounds);  // warm up (and clock up)
  double best_rate = 0;
  for (int trial = 0; trial < 200 && !stop.load(std::memory_order_relaxed); ++trial) {
    const std::uint64_t c0 = __rdtsc();
    sink = w.run(data, kRounds);
    const std::uint64_t c1 = __rdtsc();
    if (stop.load(std::memory_order_relaxed)) break;
    best_rate = std::max(best_rate, 12.0 * w.bytes * kRounds / static_cast<double>(c1 - c0));
  }
  (void)sink;
  stop = true;
  return best_rate;
}

// `threads` threads running `w` at once: their rates summed.
double measure_instruction(const Instruction& w, int threads) {
  std::atomic<bool> stop{false};
  std::vector<double> rates(static_cast<std::size_t>(std::max(1, threads)));
  std::vector<std::thread> others;
  for (std::size_t t = 1; t < rates.size(); ++t)
    others.emplace_back([&, t] { rates[t] = fastest_trial(w, stop); });
  rates[0] = fastest_trial(w, stop);
  for (std::thread& t : others) t.join();
  double sum = 0;
  for (double r : rates) sum += r;
  return sum;
}

}  // namespace

std::string ceiling_instructions() {
  std::string names;
  for (const Instruction* i : usable()) names += (names.empty() ? "" : ", ") + std::string(i->name);
  return names.empty() ? "none" : names;
}

Ceiling fastest_instruction() {
  Ceiling best{"none", 0};
  for (const Instruction* i : usable())
    if (const double rate = measure_instruction(*i, 1); rate > best.bytes_per_cycle)
      best = {i->name, rate};
  return best;
}

double measure_ceiling(const std::string& instruction, int threads) {
  for (const Instruction* i : usable())
    if (instruction == i->name) return measure_instruction(*i, threads);
  return 0;
}

}  // namespace pxflow::cpu
