// neon_cross_check: built for AArch64 by the cross compiler and run under qemu-user (ctest
// label `cross`). Checks every kernel of the ISA table compiled for AArch64 (swar and neon)
// against ref-original with the harness's exactness checker, on the synthetic corpus (seeded
// random and hostile pairs at px4flow-64, px4flow-head, 320x240 and wide radii) and, given the
// frames.txt of `cpu_path_check --dump-real`, the real frames; each group as one batch.
// Exit 0 when all match, 1 otherwise (also when the table compiles no kernel but swar here).
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "cpu_corpus.hpp"
#include "cpu_kernel.hpp"
#include "isa_table.hpp"

#if !defined(__aarch64__)
#error "neon_cross_check is built for AArch64 only"
#endif

namespace {

// The real frames that `cpu_path_check --dump-real` wrote, from its frames.txt; none (with a
// note) when the list is missing, e.g. without opencv-doc.
std::vector<pxflow::cpu_test::Group> real_corpus(const char* list_path) {
  std::vector<pxflow::cpu_test::Group> groups;
  std::ifstream list(list_path);
  if (!list) {
    std::printf("note: %s not found: real frames not checked\n", list_path);
    return groups;
  }
  std::string name, prev_path, next_path;
  int w = 0, h = 0;
  while (list >> name >> w >> h >> prev_path >> next_path) {
    std::vector<std::uint8_t> prev(static_cast<std::size_t>(w) * h), next(prev.size());
    std::ifstream(prev_path, std::ios::binary)
        .read(reinterpret_cast<char*>(prev.data()), prev.size());
    std::ifstream(next_path, std::ios::binary)
        .read(reinterpret_cast<char*>(next.data()), next.size());
    for (auto& g : pxflow::cpu_test::real_groups(name, w, h, prev.data(), next.data()))
      groups.push_back(std::move(g));
  }
  return groups;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace pxflow;
  std::vector<cpu_test::Group> groups = cpu_test::synthetic_corpus(40);
  if (argc > 1)
    for (auto& g : real_corpus(argv[1])) groups.push_back(std::move(g));
  int failed = 0, total = 0, kernels = 0;
  std::string names;
  for (const cpu::IsaInfo& isa : cpu::isa_table()) {
    if (!isa.compiled()) continue;
    ++kernels;
    names += (names.empty() ? "" : ", ") + std::string(isa.name);
    if (!isa.cpu_has()) {
      std::printf("FAIL %s: the emulated CPU lacks it (needs %s)\n", isa.name, isa.needs);
      ++failed;
      continue;
    }
    const cpu::IsaKernel* k = &isa.kernel();
    const auto run = [k](std::span<const FramePair> pairs, const Params& p,
                         std::span<PoiRecord> out) {
      const std::size_t per_pair = out.size() / pairs.size();
      OpCounts counts;
      for (std::size_t n = 0; n < pairs.size(); ++n)
        cpu::run_flow(*k, pairs[n], p, out.subspan(n * per_pair, per_pair), counts);
    };
    for (const cpu_test::Group& g : groups) {
      ++total;
      failed += cpu_test::check_group(isa.name, g, run) ? 0 : 1;
    }
  }
  std::printf("aarch64: %d of %d group runs failed (kernels: %s)\n", failed, total, names.c_str());
  if (kernels < 2) {
    std::printf("FAIL no AArch64 kernel beside the portable one was compiled\n");
    return 1;
  }
  return failed == 0 ? 0 : 1;
}
