// SPEC §8: the known answers, from the firmware compiled on a PC, for every reference variant.
#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>

#include "estimate.hpp"
#include "run_helpers.hpp"
#include "synthetic.hpp"

using namespace pxflow;
using test::run_ref;

namespace {

FrameResult estimate_with(RefVariant v, const OwnedPair& pair, const Params& p) {
  return estimate_flow(run_ref(v, pair.view(), p), p);
}

// Bits, not closeness: 2.0f and 1.9999999f are different answers.
void require_bits(float got, float expected) {
  REQUIRE(std::bit_cast<std::uint32_t>(got) == std::bit_cast<std::uint32_t>(expected));
}

// A smooth texture sampled twice at 2x resolution: next is prev moved by (+1.5, +2) exactly,
// in the continuous sense, without any averaging of our own.
OwnedPair smooth_half_pixel_pair() {
  const int W = 64, H = 64, HW = 2 * W, HH = 2 * H;
  Rng rng(2022);
  std::vector<int> hi(HW * HH);
  for (auto& v : hi) v = rng.uniform(0, 255);
  for (int pass = 0; pass < 6; ++pass) {  // smooth until a half-pixel step is nearly linear
    std::vector<int> out(hi.size());
    for (int y = 0; y < HH; ++y)
      for (int x = 0; x < HW; ++x) {
        int sum = 0;
        for (int d = -1; d <= 1; ++d)
          sum +=
              hi[y * HW + std::clamp(x + d, 0, HW - 1)] + hi[std::clamp(y + d, 0, HH - 1) * HW + x];
        out[y * HW + x] = sum / 6;
      }
    hi = out;
  }
  int lo = 255, top = 0;
  for (int v : hi) lo = std::min(lo, v), top = std::max(top, v);
  auto T = [&](int x, int y) {  // stretched to the full 8-bit range, clamped at the borders
    const int v = hi[std::clamp(y, 0, HH - 1) * HW + std::clamp(x, 0, HW - 1)];
    return static_cast<std::uint8_t>((v - lo) * 255 / std::max(1, top - lo));
  };
  OwnedPair op{"smooth(+1.5,+2)", W, H, std::vector<std::uint8_t>(W * H),
               std::vector<std::uint8_t>(W * H)};
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      op.prev[y * W + x] = T(2 * x, 2 * y);
      op.next[y * W + x] = T(2 * x - 3, 2 * y - 4);  // prev at (x - 1.5, y - 2)
    }
  return op;
}

}  // namespace

TEST_CASE("random texture shifted by (+2, -1) gives flow (2, -1), quality 255", "[known]") {
  OwnedPair op{"shift(+2,-1)", 64, 64, {}, {}};
  Rng rng(1);
  op.prev.resize(64 * 64);
  for (auto& v : op.prev) v = static_cast<std::uint8_t>(rng.uniform(0, 255));
  shift_into(op.prev, op.next, 64, 64, +2, -1, 7);  // next(x, y) = prev(x-2, y+1)
  REQUIRE(op.next[10 * 64 + 20] == op.prev[11 * 64 + 18]);
  for (RefVariant v : kRefVariants)
    for (bool hf : {true, false}) {
      CAPTURE(ref_variant_name(v), hf);
      Params p;
      p.hist_filter = hf;
      const FrameResult r = estimate_with(v, op, p);
      require_bits(r.flow_x, 2.0f);
      require_bits(r.flow_y, -1.0f);
      CHECK(r.quality == 255);
      CHECK(r.meancount == 64);
    }
}

TEST_CASE("smoothed texture shifted by (+1.5, +2) gives flow (1.5, 2) with HF off", "[known]") {
  const OwnedPair op = smooth_half_pixel_pair();
  for (RefVariant v : kRefVariants) {
    CAPTURE(ref_variant_name(v));
    Params p;
    p.hist_filter = false;
    const FrameResult r = estimate_with(v, op, p);
    require_bits(r.flow_x, 1.5f);
    require_bits(r.flow_y, 2.0f);
    CHECK(r.quality == 255);
  }
}

TEST_CASE("a constant image gives flow 0, quality 0", "[known]") {
  OwnedPair op{"constant", 64, 64, std::vector<std::uint8_t>(64 * 64, 77),
               std::vector<std::uint8_t>(64 * 64, 77)};
  for (RefVariant v : kRefVariants)
    for (bool hf : {true, false}) {
      Params p;
      p.hist_filter = hf;
      const auto recs = run_ref(v, op.view(), p);
      for (const auto& rec : recs) REQUIRE(rec.status == kDropped);  // feature 0 < 40
      const FrameResult r = estimate_flow(recs, p);
      require_bits(r.flow_x, 0.0f);
      require_bits(r.flow_y, 0.0f);
      CHECK(r.quality == 0);
    }
}
