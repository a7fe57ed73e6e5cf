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

// Independent noise in prev and next, then each POI's 8x8 block of prev copied into next at
// (i + dx, j), dx = 1 for the first two thirds of the grid's POIs and 2 for the rest: every POI's
// integer match is exact (SAD 0) and no half step beats it, so hx is 2 or 4 and HF's mean over
// the window is non-dyadic (6 x 65 + 3 x 67 over 9 at 9 POIs: flow_x = 4/3).
OwnedPair non_dyadic_pair(const Params& p, std::uint64_t seed) {
  const int w = p.width, h = p.height;
  OwnedPair o{"non-dyadic flow_x", w, h, {}, {}};
  Rng rng(seed);
  o.prev.resize(static_cast<std::size_t>(w * h));
  o.next.resize(o.prev.size());
  for (auto& v : o.prev) v = static_cast<std::uint8_t>(rng.uniform(0, 255));
  for (auto& v : o.next) v = static_cast<std::uint8_t>(rng.uniform(0, 255));
  const std::vector<int> xs = grid_axis(w, p), ys = grid_axis(h, p);
  const std::size_t pois = xs.size() * ys.size();
  for (std::size_t n = 0; n < pois; ++n) {
    const int i = xs[n % xs.size()], j = ys[n / xs.size()], dx = 3 * n < 2 * pois ? 1 : 2;
    for (int r = 0; r < 8; ++r)
      for (int c = 0; c < 8; ++c) o.next[(j + r) * w + i + dx + c] = o.prev[(j + r) * w + i + c];
  }
  return o;
}

}  // namespace

// The team's merged histogram has two bins of zeros past its top bin, which the window of a peak
// there reads at S = 31; the word after them is the previous frame's flow_x bits (bits[0]), so
// one zero bin short makes a non-dyadic flow_x (low bits set) leak into the next frame of the
// same cluster run. Kills the mutant fast_serial.c:30:37:const-1 (docs/measurements/
// mutation-campaigns.md), which the outermost-bins test below, whose frames before a top-bin
// peak have dyadic flows, let survive.
TEST_CASE("gap8 fast: a top-bin peak at S = 31 after a non-dyadic flow_x", "[gap8][no-sanitizer]") {
  Params p = profile("px4flow-64");  // HF on
  p.width = p.height = 96;           // grid 32, 41, 50: 9 POIs whose blocks do not overlap
  p.search_radius = 31;
  p.blocks = 3;
  p.min_count = 2;
  validate(p);
  REQUIRE(grid_axis(p.width, p).size() == 3);
  for (int cores : {8, 1}) {
    Gap8Backend backend(Gap8Variant::kFast, gap8_host::RunOptions{cores, true, false});
    const std::vector<OwnedPair> pairs{non_dyadic_pair(p, 5), half_pixel_edge_pair(96, 96, 31, 6)};
    require_exact({"gap8-fast on " + std::to_string(cores) + " cores", "non-dyadic then top bin",
                   "96x96 S=31 B=3"},
                  pairs, p, batch_run_of(backend));
  }
}

// HF's window at the histogram's ends (SPEC §5's clamp): the fast variant's team estimate sums
// p - 2 .. p + 2 over two bins of zeros on each side, also at S = 31 (the largest histogram).
TEST_CASE("gap8 fast: flows at the histogram's outermost bins", "[gap8][no-sanitizer]") {
  Gap8Backend backend(Gap8Variant::kFast, gap8_host::RunOptions{8, true, false});
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
