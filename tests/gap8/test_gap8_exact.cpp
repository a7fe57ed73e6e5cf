// The GAP8 kernel's records are ref-original's, byte for byte, on random, hostile and real pairs
// at px4flow-64 and px4flow-head, on 1 and 8 cores, in every variant; and on a larger frame that
// still fits L1.
#include <algorithm>
#include <catch2/catch.hpp>

#include "exact_check.hpp"
#include "gap8_backend.hpp"
#include "gap8_test_util.hpp"
#include "grid.hpp"

namespace pxflow::test {
namespace {

// The whole corpus as one batch (run() also checks the kernel's own estimate).
void check_variant(const Gap8VariantInfo& v, int cores, const std::string& setting, const Params& p,
                   int n_random, std::uint64_t seed) {
  Gap8Backend backend(v.id, gap8_host::RunOptions{cores, true, false});
  REQUIRE(backend.unsupported(p).empty());
  const std::string who = std::string("gap8-") + v.name + " on " + std::to_string(cores) + " cores";
  require_exact({who, "gap8 corpus", setting}, gap8_corpus(p, n_random, seed), p,
                batch_run_of(backend));
}

}  // namespace

TEST_CASE("gap8 variants are bit-exact at both profiles on 1 and 8 cores", "[gap8][no-sanitizer]") {
  for (const char* profile_name : {"px4flow-64", "px4flow-head"}) {
    const Params p = profile(profile_name);
    for (const Gap8VariantInfo& v : gap8_variants())
      for (int cores : {1, 8}) check_variant(v, cores, profile_name, p, 6, 1000 + cores);
  }
}

TEST_CASE("gap8 is bit-exact on a larger frame that fits L1, odd width included",
          "[gap8][no-sanitizer]") {
  Params p = profile("px4flow-64");
  p.width = 101;  // not a multiple of 4: the global planes' row tails are computed bytewise
  p.height = 72;
  p.search_radius = 7;
  p.blocks = 6;
  p.hist_filter = false;
  validate(p);
  for (const Gap8VariantInfo& v : gap8_variants())
    check_variant(v, 8, "101x72 S=7 B=6", p, 3, 3000);
}

namespace {

// prev(x, y) = floor((next(x + bx, y) + next(x + bx + 1, y)) / 2) over a noise texture: every
// POI's integer match is bx (at the window's edge when |bx| = S) and its half-pixel step in x is
// exact, so the frame's flow is bx + 0.5: the histogram's peak at an outermost bin when bx = S
// (top bin) or bx = -S - 1 (bin 0).
OwnedPair half_pixel_edge_pair(int w, int h, int bx, std::uint64_t seed) {
  OwnedPair o{"half-pixel edge bx=" + std::to_string(bx), w, h, {}, {}};
  Rng rng(seed);
  o.next.resize(static_cast<std::size_t>(w * h));
  for (auto& v : o.next) v = static_cast<std::uint8_t>(rng.uniform(0, 255));
  o.prev.assign(o.next.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int a = std::clamp(x + bx, 0, w - 1), b = std::clamp(x + bx + 1, 0, w - 1);
      o.prev[y * w + x] = static_cast<std::uint8_t>((o.next[y * w + a] + o.next[y * w + b]) / 2);
    }
  return o;
}

}  // namespace

// HF's window at the histogram's ends (SPEC §5's clamp): the fast variant's team estimate sums
// p - 2 .. p + 2 over two bins of zeros on each side, also at S = 31 (the largest histogram).
TEST_CASE("gap8 fast: flows at the histogram's outermost bins", "[gap8][no-sanitizer]") {
  const Gap8VariantInfo* fast = nullptr;
  for (const Gap8VariantInfo& v : gap8_variants())
    if (std::string(v.name) == "fast") fast = &v;
  REQUIRE(fast != nullptr);
  Gap8Backend backend(fast->id, gap8_host::RunOptions{8, true, false});
  const Params p64 = profile("px4flow-64");
  const std::vector<OwnedPair> low{half_pixel_edge_pair(64, 64, -p64.search_radius - 1, 1),
                                   half_pixel_edge_pair(64, 64, p64.search_radius, 2)};
  require_exact({"gap8-fast on 8 cores", "half-pixel edge", "px4flow-64"}, low, p64,
                batch_run_of(backend));
  Params p31 = p64;
  p31.width = p31.height = 80;
  p31.search_radius = 31;
  validate(p31);
  const std::vector<OwnedPair> wide{half_pixel_edge_pair(80, 80, 31, 3),
                                    half_pixel_edge_pair(80, 80, -32, 4)};
  require_exact({"gap8-fast on 8 cores", "half-pixel edge", "80x80 S=31"}, wide, p31,
                batch_run_of(backend));
}

}  // namespace pxflow::test
