// The three reference variants produce identical records (SPEC §6) on seeded random pairs,
// hostile patterns and real frames, at both profiles and at larger frames.
#include <catch2/catch.hpp>
#include <cstring>

#include "frame_io.hpp"
#include "frame_ops.hpp"
#include "run_helpers.hpp"
#include "sample_data.hpp"
#include "synthetic.hpp"

using namespace pxflow;
using test::run_ref;

namespace {

struct Setup {
  const char* name;
  Params params;
};

std::vector<Setup> setups() {
  auto sized = [](Params p, int w, int h, int S, int B) {
    p.width = w, p.height = h, p.search_radius = S, p.blocks = B;
    return p;
  };
  return {{"px4flow-64", profile("px4flow-64")},
          {"px4flow-head", profile("px4flow-head")},
          {"160x120 S=6 B=10", sized(Params{}, 160, 120, 6, 10)},
          {"97x75 S=3 B=13", sized(Params{}, 97, 75, 3, 13)}};
}

// Records of all three variants, compared byte for byte; reports the first differing POI.
void require_variants_agree(const FramePair& f, const Params& p, const std::string& what) {
  const auto a = run_ref(RefVariant::kOriginal, f, p);
  for (RefVariant v : {RefVariant::kLocal, RefVariant::kGlobal}) {
    const auto b = run_ref(v, f, p);
    REQUIRE(a.size() == b.size());
    for (std::size_t n = 0; n < a.size(); ++n) {
      INFO(what << ": " << ref_variant_name(v) << " differs from ref-original at POI " << n);
      REQUIRE(std::memcmp(&a[n], &b[n], sizeof(PoiRecord)) == 0);
    }
  }
}

Frame real_frame(const char* name) {
  return load_frame(std::string(kSampleDataDir) + "/" + name, std::nullopt);
}

}  // namespace

TEST_CASE("variants agree on seeded random pairs", "[variants]") {
  for (const auto& s : setups()) {
    const int seeds = s.params.width == 64 ? 150 : 25;
    for (int seed = 0; seed < seeds; ++seed) {
      const OwnedPair op = random_pair(s.params.width, s.params.height, s.params.search_radius,
                                       static_cast<std::uint64_t>(seed));
      require_variants_agree(op.view(), s.params, std::string(s.name) + " " + op.name);
    }
  }
}

TEST_CASE("variants agree on hostile patterns", "[variants]") {
  for (const auto& s : setups())
    for (const auto& op : hostile_pairs(s.params.width, s.params.height, s.params.search_radius))
      require_variants_agree(op.view(), s.params, std::string(s.name) + " " + op.name);
}

TEST_CASE("variants agree on real frames: full size, crops, and 64x64 binned", "[variants][real]") {
  for (auto [a, b] : {std::pair{"rubberwhale1.png", "rubberwhale2.png"},
                      std::pair{"basketball1.png", "basketball2.png"}}) {
    const Frame prev = real_frame(a), next = real_frame(b);
    Params p;
    p.width = prev.width, p.height = prev.height;
    require_variants_agree({prev.view(), next.view()}, p, std::string(a) + " full size");
    p.blocks = 24, p.search_radius = 7;
    require_variants_agree({prev.view(), next.view()}, p, std::string(a) + " full size S=7 B=24");

    const Frame cp = crop(prev, 100, 50, 64, 64), cn = crop(next, 100, 50, 64, 64);
    for (const Params& q : {profile("px4flow-64"), profile("px4flow-head")})
      require_variants_agree({cp.view(), cn.view()}, q, std::string(a) + " crop 64x64");

    // 4x4 binning of a 256x256 window, the way the PX4FLOW camera makes 64x64 frames.
    const Frame bp = bin(crop(prev, 0, 0, 256, 256), 4), bn = bin(crop(next, 0, 0, 256, 256), 4);
    REQUIRE(bp.width == 64);
    require_variants_agree({bp.view(), bn.view()}, Params{}, std::string(a) + " binned 64x64");
  }
}
