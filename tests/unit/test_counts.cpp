// SPEC §6: the work each variant counts, on a pair where all 64 POIs pass, and how the counts
// follow the statuses elsewhere (docs/counting.md).
#include <catch2/catch.hpp>

#include "counting_model.hpp"
#include "run_helpers.hpp"
#include "synthetic.hpp"

using namespace pxflow;

namespace {

OwnedPair all_pass_pair() {
  OwnedPair op{"shift(+2,-1)", 64, 64, std::vector<std::uint8_t>(64 * 64), {}};
  Rng rng(11);
  for (auto& v : op.prev) v = static_cast<std::uint8_t>(rng.uniform(0, 255));
  shift_into(op.prev, op.next, 64, 64, 2, -1, 5);
  return op;
}

}  // namespace

TEST_CASE("all 64 POIs accepted: 91,520 SAD ops and the paper's interpolation counts", "[counts]") {
  const OwnedPair op = all_pass_pair();
  const std::pair<RefVariant, std::uint64_t> expected[] = {
      {RefVariant::kOriginal, 49152}, {RefVariant::kLocal, 19200}, {RefVariant::kGlobal, 12288}};
  for (auto [v, interpolations] : expected) {
    CAPTURE(ref_variant_name(v));
    OpCounts c;
    const auto recs = test::run_ref(v, op.view(), Params{}, &c);
    for (const auto& r : recs) REQUIRE(r.status == kAccepted);
    CHECK(c.counted);
    CHECK(c.sad_ops == 91520);  // 64 x (6 feature + 81 x 16 search + 8 x 16 half-pixel)
    CHECK(c.interpolations == interpolations);
  }
}

TEST_CASE("counts follow the statuses: dropped, rejected and accepted POIs", "[counts]") {
  for (std::uint64_t seed = 0; seed < 30; ++seed) {
    for (const Params& p : {profile("px4flow-64"), profile("px4flow-head")}) {
      const OwnedPair op = random_pair(64, 64, p.search_radius, seed);
      const std::uint64_t candidates = (2 * p.search_radius + 1) * (2 * p.search_radius + 1);
      OpCounts orig, local, global;
      const auto recs = test::run_ref(RefVariant::kOriginal, op.view(), p, &orig);
      test::run_ref(RefVariant::kLocal, op.view(), p, &local);
      test::run_ref(RefVariant::kGlobal, op.view(), p, &global);
      std::uint64_t searched = 0, accepted = 0;
      for (const auto& r : recs) {
        searched += r.status != kDropped;
        accepted += r.status == kAccepted;
      }
      const std::uint64_t sad_ops = 6 * recs.size() + 16 * candidates * searched + 128 * accepted;
      CHECK(orig.sad_ops == sad_ops);
      CHECK(local.sad_ops == sad_ops);
      CHECK(global.sad_ops == sad_ops);
      CHECK(orig.interpolations == 768 * accepted);
      CHECK(local.interpolations == 300 * accepted);
      CHECK(global.interpolations == 3 * 64 * 64);  // per frame, before any matching
      // The model `pxflow check` holds backends to gives each variant's own counts.
      for (const auto& [v, c] :
           {std::pair{RefVariant::kOriginal, orig}, std::pair{RefVariant::kLocal, local},
            std::pair{RefVariant::kGlobal, global}}) {
        const OpCounts m = model_counts(v, recs, p, 1);
        CHECK(m.sad_ops == c.sad_ops);
        CHECK(m.interpolations == c.interpolations);
      }
    }
  }
}
