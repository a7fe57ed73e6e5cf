#include "psadbw_ceiling.hpp"

#include <x86intrin.h>

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

}  // namespace

Ceiling measure_ceiling() {
  alignas(64) static std::uint8_t data[768];
  for (int i = 0; i < 768; ++i) data[i] = static_cast<std::uint8_t>(i * 37);
  struct Width {
    const char* name;
    int bytes;
    std::uint64_t (*run)(const std::uint8_t*, std::int64_t);
  };
  const Width widths[] = {
      {"xmm", 16, psadbw_xmm}, {"ymm", 32, psadbw_ymm}, {"zmm", 64, psadbw_zmm}};
  Ceiling best;
  for (const Width& w : widths) {
    if (!may_use(w.name)) continue;
    constexpr std::int64_t kRounds = 20'000;
    volatile std::uint64_t sink = w.run(data, 100 * kRounds);  // warm up (and clock up)
    double best_rate = 0;
    for (int trial = 0; trial < 200; ++trial) {  // the fastest trial: others share this machine
      const std::uint64_t c0 = __rdtsc();
      sink = w.run(data, kRounds);
      const std::uint64_t c1 = __rdtsc();
      const double rate = 12.0 * w.bytes * kRounds / static_cast<double>(c1 - c0);
      if (rate > best_rate) best_rate = rate;
    }
    (void)sink;
    best = {w.name, best_rate};
  }
  return best;
}

double sad_bytes_per_frame(long pois, int search_radius) {
  const long candidates = (2L * search_radius + 1) * (2L * search_radius + 1);
  return static_cast<double>(pois) * static_cast<double>(candidates + 8) * 64.0;
}

}  // namespace pxflow::cpu
