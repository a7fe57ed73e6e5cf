// neon_cross_check: built for AArch64 by the cross compiler and run under qemu-user (ctest
// label `cross`). Checks the neon and swar kernels against ref-original on the synthetic corpus
// (seeded random and hostile pairs at px4flow-64, px4flow-head, 320x240 and wide radii), each
// group as one batch. Exit 0 when all match, 1 otherwise.
#include <cstdio>

#include "cpu_corpus.hpp"
#include "cpu_kernel.hpp"

#if !defined(__aarch64__)
#error "neon_cross_check is built for AArch64 only"
#endif

int main() {
  using namespace pxflow;
  int failed = 0, total = 0;
  for (const cpu::IsaKernel* k : {&cpu::neon_kernel(), &cpu::swar_kernel()}) {
    const auto run = [k](std::span<const FramePair> pairs, const Params& p,
                         std::span<PoiRecord> out) {
      const std::size_t per_pair = out.size() / pairs.size();
      OpCounts counts;
      for (std::size_t n = 0; n < pairs.size(); ++n)
        cpu::run_flow(*k, pairs[n], p, out.subspan(n * per_pair, per_pair), counts);
    };
    for (const cpu_test::Group& g : cpu_test::synthetic_corpus(40)) {
      total += static_cast<int>(g.cases.size());
      failed += cpu_test::check_group(k->name, g, run);
    }
  }
  std::printf("aarch64 neon+swar: %d of %d case runs failed\n", failed, total);
  return failed == 0 ? 0 : 1;
}
