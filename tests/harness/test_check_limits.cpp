// The limit cases of the fixed corpus (hosts/harness/check/check_limits.hpp) and the guard zones'
// messages (hosts/core/guard_zone.hpp), on predicates and buffers made here.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "check_limits.hpp"
#include "check_radius_sweep.hpp"
#include "errors.hpp"
#include "grid.hpp"
#include "guard_zone.hpp"
#include "kernel.hpp"

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
  // its largest grid is SPEC's corner: that corner's case, none of its own.
  const LimitProbe* strip = find("widest of open");
  REQUIRE(strip);
  CHECK(strip->params.width == kMaxFrameSide);
  CHECK(find("largest-square of open") == nullptr);
  CHECK(find("largest-blocks of open") == nullptr);  // SPEC's B = 255 corner, every row's case
  for (const LimitProbe& p : probes) {
    INFO(p.what());
    CHECK(std::int64_t{p.params.width} * p.params.height <= kAffordableLimitPixels);
    CHECK_NOTHROW(validate(p.params));
  }
  // Every probe once: the cases are each a distinct problem (a sweep step's planted pairs are
  // another problem than random pairs of the same parameters).
  for (std::size_t i = 0; i < probes.size(); ++i)
    for (std::size_t j = i + 1; j < probes.size(); ++j)
      CHECK_FALSE((probes[i].params == probes[j].params &&
                   (probes[i].sweep_pairs > 0) == (probes[j].sweep_pairs > 0)));
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

TEST_CASE("limits: a row's cases are the same, pair for pair, whatever other rows are selected",
          "[limits]") {
  const LimitRow small{"small", [](const Params& p) -> std::string {
                         return std::int64_t{p.width} * p.height > 5000 ? "too many pixels" : "";
                       }};
  const LimitRow open{"open", [](const Params&) { return std::string(); }};
  const LimitRow tiny{"tiny", [](const Params& p) -> std::string {
                        return std::int64_t{p.width} * p.height > 400 ? "too many pixels" : "";
                      }};
  auto of = [](std::span<const LimitRow> rows, const std::string& row) {
    std::vector<CheckCase> mine;
    for (CheckCase& c : limit_cases(rows, 3))
      if (c.for_row(row)) mine.push_back(std::move(c));
    return mine;
  };
  const LimitRow alone[] = {small}, together[] = {open, tiny, small};
  const auto a = of(alone, "small"), b = of(together, "small");
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    INFO(a[i].name << " " << a[i].setting);
    CHECK(a[i].name == b[i].name);
    CHECK(a[i].setting == b[i].setting);
    CHECK(a[i].params == b[i].params);
    REQUIRE(a[i].pairs.size() == b[i].pairs.size());
    for (std::size_t k = 0; k < a[i].pairs.size(); ++k) {
      CHECK(a[i].pairs[k].prev == b[i].pairs[k].prev);
      CHECK(a[i].pairs[k].next == b[i].pairs[k].next);
    }
  }
  // The other rows' own edges are not this row's cases.
  CHECK(std::none_of(b.begin(), b.end(), [](const CheckCase& c) {
    return std::find(c.rows.begin(), c.rows.end(), "small") == c.rows.end() && !c.rows.empty();
  }));
}

TEST_CASE("limits: the radius sweep plants the best match at every dx and dy of every radius",
          "[limits]") {
  const LimitRow open{"open", [](const Params&) { return std::string(); }};
  const LimitRow rows[] = {open};
  int radii = 0;
  for (const CheckCase& c : limit_cases(rows, 1)) {
    if (c.name != "limits/radius-sweep") continue;
    ++radii;
    const int S = c.params.search_radius;
    INFO(c.setting);
    const auto offsets = sweep_offsets(S);
    std::vector<bool> dx_seen(2 * S + 1), dy_seen(2 * S + 1);
    std::size_t planted = 0;
    for (const OwnedPair& pair : c.pairs) {
      std::vector<PoiRecord> recs(poi_count(c.params));
      OpCounts counts;
      reference_flow(RefVariant::kOriginal, pair.view(), c.params, recs, counts);
      for (const PoiRecord& r : recs) {
        const Offset o = offsets[planted++ % offsets.size()];
        if (std::abs(o.dx) > S || std::abs(o.dy) > S) {  // a decoy: the window holds noise only
          CHECK(r.sad > 0);
          continue;
        }
        CHECK((r.status == kAccepted && r.dx == o.dx && r.dy == o.dy && r.sad == 0));
        dx_seen[o.dx + S] = dy_seen[o.dy + S] = true;
      }
    }
    CHECK(planted >= offsets.size());  // every offset, in one pair or several
    CHECK(std::count(dx_seen.begin(), dx_seen.end(), false) == 0);
    CHECK(std::count(dy_seen.begin(), dy_seen.end(), false) == 0);
  }
  CHECK(radii == kMaxSearchRadius - kMinSearchRadius + 1);
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
