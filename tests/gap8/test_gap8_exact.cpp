// The GAP8 kernel's records are ref-original's, byte for byte, on random, hostile and real pairs
// at px4flow-64 and px4flow-head, on 1 and 8 cores, in every variant; and on a larger frame that
// still fits L1.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>

#include "gap8_backend.hpp"
#include "gap8_test_util.hpp"
#include "grid.hpp"
#include "run_helpers.hpp"

namespace pxflow::test {
namespace {

void check_exact(const std::string& variant, int cores, const Params& p, int n_random,
                 std::uint64_t seed) {
  Gap8Backend backend(variant, gap8_host::RunOptions{cores, true, false});
  REQUIRE(backend.unsupported(p).empty());
  const std::vector<OwnedPair> corpus = gap8_corpus(p, n_random, seed);
  std::vector<FramePair> views;
  for (const OwnedPair& o : corpus) views.push_back(o.view());
  const std::size_t pois = poi_count(p);
  std::vector<PoiRecord> got = sentinel_records(pois * views.size());
  OpCounts counts;
  backend.run(views, p, got, counts);  // also checks the kernel's own estimate
  for (std::size_t i = 0; i < views.size(); ++i) {
    const std::vector<PoiRecord> expected = run_ref(RefVariant::kOriginal, views[i], p);
    const std::vector<PoiRecord> mine(got.begin() + i * pois, got.begin() + (i + 1) * pois);
    INFO(first_difference(expected, mine, corpus[i].name));
    REQUIRE(std::memcmp(expected.data(), mine.data(), pois * sizeof(PoiRecord)) == 0);
  }
}

}  // namespace

TEST_CASE("gap8 variants are bit-exact at px4flow-64 on 1 and 8 cores", "[gap8][no-sanitizer]") {
  const Params p = profile("px4flow-64");
  for (const char* variant : {"original", "local", "global", "fast"}) {
    for (int cores : {1, 8}) {
      INFO(variant << " on " << cores << " cores");
      check_exact(variant, cores, p, 6, 1000 + cores);
    }
  }
}

TEST_CASE("gap8 variants are bit-exact at px4flow-head on 1 and 8 cores", "[gap8][no-sanitizer]") {
  const Params p = profile("px4flow-head");
  for (const char* variant : {"original", "local", "global", "fast"}) {
    for (int cores : {1, 8}) {
      INFO(variant << " on " << cores << " cores");
      check_exact(variant, cores, p, 6, 2000 + cores);
    }
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
  for (const char* variant : {"original", "local", "global", "fast"}) {
    INFO(variant);
    check_exact(variant, 8, p, 3, 3000);
  }
}

}  // namespace pxflow::test

namespace pxflow::test {
namespace {

long env_or(const char* name, long fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtol(v, nullptr, 10) : fallback;
}

}  // namespace

// The fast kernel is not a registry row, so `pxflow check` cannot fuzz it: this test does what
// `pxflow check --cases N --seed S` does for a row (the same random_pair seeds, batches of 256),
// N pairs at each of the two profiles, on 8 cores. 32 pairs by default (in ctest); a campaign:
//   GAP8_FAST_PAIRS=1000 GAP8_FAST_SEED=2026 build/tests/gap8/gap8_tests "[fast-campaign]"
TEST_CASE("gap8 fast campaign: random pairs at px4flow-64 and px4flow-head",
          "[gap8][no-sanitizer][fast-campaign]") {
  const long pairs = env_or("GAP8_FAST_PAIRS", 32);
  const auto seed = static_cast<std::uint64_t>(env_or("GAP8_FAST_SEED", 2026));
  for (const char* name : {"px4flow-64", "px4flow-head"}) {
    const Params p = profile(name);
    Gap8Backend backend("fast", gap8_host::RunOptions{8, true, false});
    const std::size_t pois = poi_count(p);
    long done = 0;
    while (done < pairs) {
      const int n = static_cast<int>(std::min<long>(256, pairs - done));
      std::vector<OwnedPair> batch;
      for (int k = 0; k < n; ++k)
        batch.push_back(random_pair(p.width, p.height, p.search_radius,
                                    seed * 1000000007ull + static_cast<std::uint64_t>(done + k)));
      std::vector<FramePair> views;
      for (const OwnedPair& o : batch) views.push_back(o.view());
      std::vector<PoiRecord> got = sentinel_records(pois * views.size());
      OpCounts counts;
      backend.run(views, p, got, counts);  // also checks the kernel's own estimate
      for (std::size_t i = 0; i < views.size(); ++i) {
        const std::vector<PoiRecord> expected = run_ref(RefVariant::kOriginal, views[i], p);
        const std::vector<PoiRecord> mine(got.begin() + i * pois, got.begin() + (i + 1) * pois);
        INFO(name << ": " << first_difference(expected, mine, batch[i].name));
        REQUIRE(std::memcmp(expected.data(), mine.data(), pois * sizeof(PoiRecord)) == 0);
      }
      done += n;
    }
    WARN(name << ": " << done << " pairs bit-exact");
  }
}

}  // namespace pxflow::test
