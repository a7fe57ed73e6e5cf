// The limit cases of the fixed corpus (hosts/harness/check_limits.hpp) and the guard zones'
// messages (hosts/core/guard_zone.hpp), on predicates and buffers made here.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <vector>

#include "check_limits.hpp"
#include "errors.hpp"
#include "grid.hpp"
#include "guard_zone.hpp"

namespace pxflow::test {

using Catch::Matchers::Contains;

TEST_CASE("limits: the search finds the largest accepted value, its neighbour refused",
          "[limits]") {
  for (int edge : {1, 2, 19, 100, 8191, 8192}) {
    INFO(edge);
    const auto found = largest_accepted(1, 8192, [&](int v) { return v <= edge; });
    REQUIRE(found.has_value());
    CHECK(*found == edge);
  }
  CHECK_FALSE(largest_accepted(5, 10, [](int) { return false; }).has_value());
}

TEST_CASE("limits: a row's predicate gives its own edges, deduplicated with SPEC's corners",
          "[limits]") {
  // A device with room for 5000 pixels and 100 POIs: squares up to 70x70 (4900), strips 263x19
  // (4997) and 19x263, and at 64x64 the largest B with at most 100 POIs.
  const LimitRow small{"small", [](const Params& p) -> std::string {
                         if (std::int64_t{p.width} * p.height > 5000) return "too many pixels";
                         if (poi_count(p) > 100) return "too many POIs";
                         return {};
                       }};
  const LimitRow open{"open", [](const Params&) { return std::string(); }};
  const LimitRow rows[] = {small, open};
  const auto probes = limit_probes(rows);
  auto find = [&](const std::string& what) -> const LimitProbe* {
    for (const LimitProbe& p : probes)
      if (p.what() == what) return &p;
    return nullptr;
  };
  const LimitProbe* square = find("largest-square of small");
  REQUIRE(square);
  CHECK((square->params.width == 70 && square->params.height == 70));
  const LimitProbe* wide = find("widest of small");
  REQUIRE(wide);
  CHECK((wide->params.width == 263 && wide->params.height == 19));
  const LimitProbe* blocks = find("largest-blocks of small");
  REQUIRE(blocks);
  CHECK(poi_count(blocks->params) <= 100);
  Params more = blocks->params;
  ++more.blocks;
  CHECK(poi_count(more) > 100);
  // The unlimited row reaches the side limit with cheap strips, never an 8192x8192 square, and
  // its largest grid is SPEC's corner: one case naming it.
  const LimitProbe* strip = find("widest of open");
  REQUIRE(strip);
  CHECK(strip->params.width == kMaxFrameSide);
  CHECK(find("largest-square of open") == nullptr);
  CHECK(find("largest-blocks of open") != nullptr);
  for (const LimitProbe& p : probes) {
    INFO(p.what());
    CHECK(std::int64_t{p.params.width} * p.params.height <= kAffordableLimitPixels);
    CHECK_NOTHROW(validate(p.params));
  }
  // Every probe once: the cases are each a distinct problem.
  for (std::size_t i = 0; i < probes.size(); ++i)
    for (std::size_t j = i + 1; j < probes.size(); ++j)
      CHECK_FALSE(probes[i].params == probes[j].params);
  // SPEC's corners are there whatever the rows: radius 1 and 31, B 1 and 255, FT 0 and 65535.
  const auto cases = limit_cases({}, 1);
  auto has = [&](auto pred) {
    return std::any_of(cases.begin(), cases.end(),
                       [&](const CheckCase& c) { return pred(c.params); });
  };
  CHECK(has([](const Params& p) { return p.search_radius == kMaxSearchRadius; }));
  CHECK(has([](const Params& p) { return p.search_radius == kMinSearchRadius; }));
  CHECK(has([](const Params& p) { return p.blocks == kMaxBlocks; }));
  CHECK(has([](const Params& p) { return p.blocks == kMinBlocks; }));
  CHECK(has([](const Params& p) { return p.feature_threshold == kMaxThreshold; }));
  CHECK(has([](const Params& p) {
    return p.feature_threshold == 0 && p.sad_threshold == kMaxThreshold;
  }));
  CHECK(has([](const Params& p) { return p.width % 2 == 1 && p.height % 2 == 0; }));
  for (const CheckCase& c : cases) {
    CHECK(is_limit_case(c));
    CHECK_FALSE(c.pairs.empty());
  }
}

TEST_CASE("guard zones: a changed byte says how far past the output it is", "[limits]") {
  std::vector<std::uint8_t> zone(kGuardBytes);
  fill_guard(zone);
  CHECK_NOTHROW(check_guard_after(zone, 64, "dev"));
  CHECK_NOTHROW(check_guard_before(zone, "dev"));
  zone[0] = 0;
  zone[9] = 1;  // the farthest byte counts
  CHECK_THROWS_AS(check_guard_after(zone, 64, "dev"), BackendError);
  CHECK_THROWS_WITH(check_guard_after(zone, 64, "dev"),
                    "dev: wrote past its output (10 bytes after record 63)");
  fill_guard(zone);
  zone[kGuardBytes - 3] = 0;  // 3 bytes before the first record
  CHECK_THROWS_WITH(check_guard_before(zone, "dev"),
                    "dev: wrote before its output (3 bytes before record 0)");
}

}  // namespace pxflow::test
