// The traps a port falls into (SPEC §3, §7): round-up averaging, the diagonal formula, tie order
// in the search and in the half-pixel vote, values exactly at the thresholds, canonical zeros.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstring>

#include "run_helpers.hpp"
#include "spec_oracle.hpp"
#include "synthetic.hpp"

using namespace pxflow;
using test::run_ref;

namespace {

// next tiles rows (1, 0) over (1, 2): every horizontal pair sums to an odd number (floor and
// round-up differ) and every 2x2 window is SPEC §3's diagonal example in some orientation.
OwnedPair trap_pair() {
  OwnedPair op{"trap", 64, 64, std::vector<std::uint8_t>(64 * 64),
               std::vector<std::uint8_t>(64 * 64)};
  Rng rng(3);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      static const int tile[2][2] = {{1, 0}, {1, 2}};
      op.next[y * 64 + x] = static_cast<std::uint8_t>(tile[y & 1][x & 1]);
      op.prev[y * 64 + x] = static_cast<std::uint8_t>(rng.uniform(0, 30));
    }
  return op;
}

}  // namespace

TEST_CASE("SPEC's diagonal example: rows (1,0) over (1,2) give d = 0", "[traps]") {
  const std::uint8_t px[4] = {1, 0, 1, 2};
  const FrameView v{2, 2, 2, px};
  using namespace oracle;
  CHECK(half_value(v, 0, 0, 1, 0, 0, {}) == 0);
  CHECK(half_value(v, 0, 0, 1, 0, 0, {Rounding::kFloor, Diagonal::kFourPixelMean}) == 1);
  CHECK(half_value(v, 0, 0, 1, 0, 0, {Rounding::kFloor, Diagonal::kVerticalFirst}) == 1);
  CHECK(half_value(v, 0, 0, 1, 0, 0, {Rounding::kRoundUp, Diagonal::kTwoHorizontalAverages}) == 2);
}

TEST_CASE("half-pixel SADs use floor averages and the two-horizontal diagonal", "[traps]") {
  const OwnedPair op = trap_pair();
  const FramePair f = op.view();
  const Params p;
  using namespace oracle;
  const Rules wrong[] = {{Rounding::kRoundUp, Diagonal::kTwoHorizontalAverages},
                         {Rounding::kFloor, Diagonal::kFourPixelMean},
                         {Rounding::kFloor, Diagonal::kVerticalFirst}};
  for (RefVariant v : kRefVariants) {
    CAPTURE(ref_variant_name(v));
    int checked = 0, wrong_rule_differs[3] = {0, 0, 0};
    for (const auto& r : run_ref(v, f, p)) {
      if (r.status != kAccepted) continue;
      for (int k = 0; k < 8; ++k) {
        CAPTURE(r.x, r.y, k);
        REQUIRE(r.sub[k] == half_sad(f, r.x, r.y, r.dx, r.dy, k, {}));
        for (int w = 0; w < 3; ++w)
          wrong_rule_differs[w] += r.sub[k] != half_sad(f, r.x, r.y, r.dx, r.dy, k, wrong[w]);
      }
      ++checked;
    }
    CHECK(checked == 64);
    // The input is discriminating: each wrong rule would have produced other SADs here.
    for (int w = 0; w < 3; ++w) CHECK(wrong_rule_differs[w] >= 64);
  }
}

TEST_CASE("sub[] matches the spec oracle on random pairs at every profile", "[traps]") {
  using namespace oracle;
  int checked = 0;
  for (const Params& base : {profile("px4flow-64"), profile("px4flow-head")})
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
      const OwnedPair op = random_pair(64, 64, base.search_radius, seed);
      for (const auto& r : run_ref(RefVariant::kOriginal, op.view(), base)) {
        if (r.status != kAccepted) continue;
        for (int k = 0; k < 8; ++k)
          REQUIRE(r.sub[k] == half_sad(op.view(), r.x, r.y, r.dx, r.dy, k, {}));
        ++checked;
      }
    }
  CHECK(checked > 500);
}

TEST_CASE("integer search: a tie keeps the first candidate in raster order", "[traps]") {
  // Period 2 in x and y, next == prev: SAD is 0 at every even (dx, dy); raster order starts at
  // (-S, -S). A search that starts at the centre or replaces on <= would answer otherwise.
  for (int S : {4, 8}) {
    Params p;
    p.search_radius = S;
    for (int odd : {0, 1}) {
      std::vector<std::uint8_t> px(64 * 64);
      for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
          px[y * 64 + x] = static_cast<std::uint8_t>(40 * (x & 1) + 90 * (y & 1));
      OwnedPair op{"periodic", 64, 64, px, px};
      if (odd) shift_into(px, op.next, 64, 64, 1, 0, 0);  // ties now at odd dx
      for (RefVariant v : kRefVariants)
        for (const auto& r : run_ref(v, op.view(), p)) {
          REQUIRE(r.status == kAccepted);
          REQUIRE(r.sad == 0);
          REQUIRE(r.dx == (odd ? -S + 1 : -S));
          REQUIRE(r.dy == -S);
          REQUIRE(r.dir == kDirNone);  // no half step beats an exact match
        }
    }
  }
}

TEST_CASE("half-pixel vote: strictly smaller wins, ties keep the lower k", "[traps]") {
  long tie_cases = 0, half_wins = 0, integer_kept = 0;
  for (std::uint64_t seed = 0; seed < 400; ++seed) {
    Params p;
    p.hist_filter = seed % 2;
    const OwnedPair op = random_pair(64, 64, p.search_radius, seed);
    for (const auto& r : run_ref(RefVariant::kOriginal, op.view(), p)) {
      if (r.status != kAccepted) continue;
      const auto* best = std::min_element(r.sub, r.sub + 8);  // first minimum
      const int expect = *best < r.sad ? static_cast<int>(best - r.sub) : kDirNone;
      REQUIRE(int{r.dir} == expect);
      if (std::count(r.sub, r.sub + 8, *best) > 1 && *best < r.sad) ++tie_cases;
      (expect == kDirNone ? integer_kept : half_wins)++;
    }
  }
  INFO("ties " << tie_cases << ", half wins " << half_wins << ", integer kept " << integer_kept);
  CHECK(tie_cases > 0);  // the corpus really exercises the tie rule
  CHECK(half_wins > 0);
  CHECK(integer_kept > 0);
}

TEST_CASE("feature exactly at FT is kept, one below is dropped", "[traps]") {
  // Flat prev with one bump per POI's central 4x4: an interior pixel has 4 neighbours inside
  // the 4x4 (bump 10 -> feature 40), an edge pixel 3 (bump 13 -> 39).
  std::vector<std::uint8_t> px(64 * 64, 100);
  px[(5 + 2 + 1) * 64 + (5 + 2 + 1)] = 110;   // POI (5, 5): Q(1, 1)
  px[(5 + 2 + 0) * 64 + (11 + 2 + 1)] = 113;  // POI (11, 5): Q(1, 0)
  OwnedPair op{"ft", 64, 64, px, px};
  for (RefVariant v : kRefVariants) {
    const auto recs = run_ref(v, op.view(), Params{});
    CHECK(recs[0].feature == 40);
    CHECK(recs[0].status != kDropped);
    CHECK(recs[1].feature == 39);
    CHECK(recs[1].status == kDropped);
    CHECK(recs[2].feature == 0);
  }
}

TEST_CASE("SAD exactly at VT is rejected, one below is accepted", "[traps]") {
  const OwnedPair op = random_pair(64, 64, 4, 2);  // shift + noise: non-zero best SADs
  Params loose;
  loose.sad_threshold = 65535;
  const auto base = run_ref(RefVariant::kOriginal, op.view(), loose);
  int tried = 0;
  for (std::size_t n = 0; n < base.size() && tried < 5; ++n) {
    if (base[n].status != kAccepted || base[n].sad == 0) continue;
    ++tried;
    for (RefVariant v : kRefVariants) {
      Params p = loose;
      p.sad_threshold = base[n].sad;
      CHECK(run_ref(v, op.view(), p)[n].status == kRejected);
      p.sad_threshold = base[n].sad + 1;
      CHECK(run_ref(v, op.view(), p)[n].status == kAccepted);
    }
  }
  CHECK(tried == 5);
}

TEST_CASE("fields a status does not define are exactly zero", "[traps]") {
  int seen[3] = {0, 0, 0};
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    const OwnedPair op = random_pair(64, 64, 4, seed);
    for (RefVariant v : kRefVariants)
      for (const auto& r : run_ref(v, op.view(), Params{})) {
        REQUIRE(r.pad0 == 0);
        REQUIRE(r.pad1 == 0);
        ++seen[r.status];
        if (r.status == kAccepted) continue;
        REQUIRE(r.dir == kDirNone);
        REQUIRE(std::all_of(r.sub, r.sub + 8, [](auto s) { return s == 0; }));
        REQUIRE(r.hx == 0);
        REQUIRE(r.hy == 0);
        if (r.status == kDropped) {
          REQUIRE(r.dx == 0);
          REQUIRE(r.dy == 0);
          REQUIRE(r.sad == 0);
        }
      }
  }
  CHECK(seen[kDropped] > 0);
  CHECK(seen[kRejected] > 0);
  CHECK(seen[kAccepted] > 0);
}
