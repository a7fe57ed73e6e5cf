// The GAP8 backends beyond bit-exactness: the registry rows, the L1 limit, the device clock, the
// work counts, the chunked split and a known answer.
#include <catch2/catch.hpp>
#include <cstring>

#include "errors.hpp"
#include "estimate.hpp"
#include "exact_check.hpp"
#include "gap8_backend.hpp"
#include "gap8_test_util.hpp"
#include "gap8_variants.hpp"
#include "grid.hpp"
#include "registry.hpp"
#include "run_helpers.hpp"

namespace pxflow::test {

TEST_CASE("gap8 rows: one per variant, registered and able to run here", "[gap8]") {
  for (const Gap8VariantInfo& v : gap8_variants()) {
    const BackendRow& row = find_backend(std::string("gap8-") + v.name);
    CHECK(row.family == "gap8");
    CHECK(row.probe() == "");
    CHECK(row.create(BackendOptions{}) != nullptr);
  }
  CHECK(gap8_variants().size() == 4);  // original, local, global (the paper's) and fast
  CHECK_THROWS_AS(find_gap8_variant("orignal"), InputError);
}

TEST_CASE("gap8 refuses what does not fit L1, with the reason", "[gap8]") {
  Gap8Backend original(Gap8Variant::kOriginal, {}), global(Gap8Variant::kGlobal, {});
  CHECK(original.unsupported(profile("px4flow-64")).empty());
  CHECK(global.unsupported(profile("px4flow-64")).empty());
  Params vga = profile("px4flow-64");
  vga.width = 640;
  vga.height = 480;
  CHECK(original.unsupported(vga).find("does not fit L1") == 0);
  Params mid = profile("px4flow-64");
  mid.width = mid.height = 128;  // two frames fit, five (with the planes) do not
  CHECK(original.unsupported(mid).empty());
  CHECK(global.unsupported(mid).find("does not fit L1") == 0);
  std::vector<PoiRecord> out(poi_count(vga));
  OpCounts counts;
  std::vector<std::uint8_t> frame(640 * 480, 0);
  const FramePair pair{{640, 480, 640, frame.data()}, {640, 480, 640, frame.data()}};
  CHECK_THROWS_AS(original.run({&pair, 1}, vga, out, counts), BackendError);
}

TEST_CASE("gap8 reports model cycles and the paper's work counts", "[gap8][no-sanitizer]") {
  const Params p = profile("px4flow-64");
  const OwnedPair pair = shifted_texture_pair(64, 64, 4, 11);
  const FramePair view = pair.view();
  // Each variant is charged as the reference variant that makes half-pixel values its way.
  auto ref_of = [](Gap8HalfPixel h) {
    return h == Gap8HalfPixel::kPerPixel      ? RefVariant::kOriginal
           : h == Gap8HalfPixel::kLocalPlanes ? RefVariant::kLocal
                                              : RefVariant::kGlobal;
  };
  for (const Gap8VariantInfo& v : gap8_variants()) {
    INFO(v.name);
    Gap8Backend backend(v.id, {});
    CHECK_FALSE(backend.last_device_time().has_value());
    std::vector<PoiRecord> got = sentinel_records(poi_count(p));
    OpCounts counts, ref_counts;
    backend.run({&view, 1}, p, got, counts);
    run_ref(ref_of(v.half_pixel), view, p, &ref_counts);
    CHECK(counts.counted);
    CHECK(counts.sad_ops == ref_counts.sad_ops);
    CHECK(counts.interpolations == ref_counts.interpolations);
    const auto time = backend.last_device_time();
    REQUIRE(time.has_value());
    CHECK(time->source == "gap8-model-cycles");
    REQUIRE(time->cycles.has_value());
    CHECK(*time->cycles > 10000);
    CHECK(time->ns == Approx(*time->cycles * 20.0));  // 50 MHz
    const pxflow_gap8_result& r = backend.last_stats().pairs.at(0);
    CHECK(r.cycles_flow > r.cycles_averaging);
    CHECK(r.cycles_total >= r.cycles_dma + r.cycles_flow + r.cycles_averaging);
  }
}

TEST_CASE("gap8 chunked POI split gives the same records", "[gap8][no-sanitizer]") {
  const Params p = profile("px4flow-head");
  const std::vector<OwnedPair> corpus = gap8_corpus(p, 4, 77);
  for (int cores : {3, 8}) {
    for (Gap8Variant v :
         {Gap8Variant::kLocal, Gap8Variant::kFast}) {  // fast: tables on 3 cores too
      Gap8Backend backend(v, gap8_host::RunOptions{cores, true, true});
      require_exact({std::string("gap8-") + gap8_variant(v).name + " chunked on " +
                         std::to_string(cores) + " cores",
                     "gap8 corpus", "px4flow-head"},
                    corpus, p, batch_run_of(backend));
    }
  }
}

TEST_CASE("gap8 known answer: texture shifted by (+2, -1)", "[gap8][no-sanitizer]") {
  const Params p = profile("px4flow-64");
  OwnedPair pair{"noise/shift(2,-1)", 64, 64, std::vector<std::uint8_t>(64 * 64), {}};
  Rng rng(5);
  for (std::uint8_t& v : pair.prev) v = static_cast<std::uint8_t>(rng.uniform(0, 255));
  pair.next.resize(pair.prev.size());
  shift_into(pair.prev, pair.next, 64, 64, 2, -1, 9);
  const FramePair view = pair.view();
  Gap8Backend backend(Gap8Variant::kGlobal, {});
  std::vector<PoiRecord> got = sentinel_records(poi_count(p));
  OpCounts counts;
  backend.run({&view, 1}, p, got, counts);
  const pxflow_estimate& r = backend.last_stats().pairs.at(0).estimate;
  CHECK(r.flow_x == 2.0f);
  CHECK(r.flow_y == -1.0f);
  CHECK(r.quality == 255);
}

}  // namespace pxflow::test

namespace pxflow::test {

TEST_CASE("gap8 batch of several cluster runs: same bytes and cycles on 1 and 2 host threads",
          "[gap8][no-sanitizer]") {
  // 100 pairs at 64x64 need three cluster runs (L2 holds about 45); with two host workers they
  // are simulated side by side and merged in order.
  const Params p = profile("px4flow-64");
  std::vector<OwnedPair> owned;
  for (int i = 0; i < 100; ++i)
    owned.push_back(random_pair(p.width, p.height, p.search_radius, 2026 + i));
  std::vector<FramePair> views;
  for (const OwnedPair& o : owned) views.push_back(o.view());
  std::vector<std::string> names;
  for (const OwnedPair& o : owned) names.push_back(o.name);
  const ReferenceAnswer want = reference_answer(views, p);

  std::vector<std::vector<PoiRecord>> got;
  std::vector<std::uint64_t> cycles;
  std::vector<std::vector<pxflow_gap8_result>> results;
  for (int threads : {1, 2}) {
    Gap8Backend backend(Gap8Variant::kOriginal, {}, threads);
    got.push_back(sentinel_records(views.size() * poi_count(p)));
    OpCounts counts;
    backend.run(views, p, got.back(), counts);
    cycles.push_back(backend.last_stats().cycles);
    results.push_back(backend.last_stats().pairs);
  }
  for (const auto& g : got) {
    const Comparison c = compare_with_reference({"gap8-original", "100 random pairs", "px4flow-64"},
                                                names, p, want, g, 5);
    INFO(c.text());
    REQUIRE(c.ok());
  }
  CHECK(cycles[0] == cycles[1]);
  REQUIRE(results[0].size() == views.size());
  REQUIRE(results[1].size() == views.size());
  CHECK(std::memcmp(results[0].data(), results[1].data(),
                    results[0].size() * sizeof(pxflow_gap8_result)) == 0);
}

}  // namespace pxflow::test
