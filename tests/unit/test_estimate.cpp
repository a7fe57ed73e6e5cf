// SPEC §5: histograms, MINCOUNT, the histogram filter's window, the plain mean, quality, and
// gyro compensation, on hand-made record sets whose answers are worked out in the comments.
#include <bit>
#include <catch2/catch.hpp>

#include "estimate.hpp"

using namespace pxflow;

namespace {

std::vector<PoiRecord> accepted(std::initializer_list<std::pair<int, int>> hxy, int dropped = 0) {
  std::vector<PoiRecord> recs;
  for (auto [hx, hy] : hxy) {
    PoiRecord r{};
    r.status = kAccepted;
    r.hx = static_cast<std::int8_t>(hx);
    r.hy = static_cast<std::int8_t>(hy);
    recs.push_back(r);
  }
  for (int n = 0; n < dropped; ++n) recs.push_back(PoiRecord{});
  return recs;
}

std::vector<PoiRecord> repeat(int n, int hx, int hy) {
  std::vector<PoiRecord> recs;
  for (int i = 0; i < n; ++i) {
    auto one = accepted({{hx, hy}});
    recs.push_back(one[0]);
  }
  return recs;
}

std::uint32_t bits(float f) { return std::bit_cast<std::uint32_t>(f); }

}  // namespace

TEST_CASE("MINCOUNT: exactly MINCOUNT accepted POIs give zero flow and quality", "[estimate]") {
  for (bool hf : {true, false}) {
    Params p;
    p.hist_filter = hf;
    const FrameResult at = estimate_flow(repeat(10, 3, -2), p);
    CHECK(at.meancount == 10);
    CHECK(bits(at.flow_x) == bits(0.0f));
    CHECK(bits(at.flow_y) == bits(0.0f));
    CHECK(at.quality == 0);
    CHECK(at.histx[3 + 9] == 10);  // histograms are still filled
    const FrameResult above = estimate_flow(repeat(11, 3, -2), p);
    CHECK(bits(above.flow_x) == bits(1.5f));
    CHECK(bits(above.flow_y) == bits(-1.0f));
    CHECK(above.quality == 11 * 255 / 64);
  }
}

TEST_CASE("histogram filter: five bins around the first maximum, clipped at the ends",
          "[estimate]") {
  Params p;  // S = 4: 19 bins, bin = h + 9
  REQUIRE(hist_bins(4) == 19);
  // Peak at bin 9 (h = 0) with 6, bins 7..11 weigh in: h = -2 x1, -1 x2, 0 x6, +1 x3, +3 x5.
  // h = +3 (bin 12) is outside the window. V = 7*1 + 8*2 + 9*6 + 10*3 = 107, Wt = 12.
  std::vector<PoiRecord> recs;
  for (auto [h, n] : {std::pair{-2, 1}, {-1, 2}, {0, 6}, {1, 3}, {3, 5}}) {
    auto more = repeat(n, h, 0);
    recs.insert(recs.end(), more.begin(), more.end());
  }
  const FrameResult r = estimate_flow(recs, p);
  CHECK(bits(r.flow_x) == bits((107.0f / 12.0f - 9.0f) / 2.0f));
  CHECK(bits(r.flow_y) == bits(0.0f));

  // First maximum wins: bins 2 and 16 both hold 6; the window is [0, 4], clipped at 0.
  recs = repeat(6, -7, 0);
  auto later = repeat(6, 7, 0);
  recs.insert(recs.end(), later.begin(), later.end());
  const FrameResult first = estimate_flow(recs, p);
  CHECK(bits(first.flow_x) == bits((2.0f - 9.0f) / 2.0f));

  // Peak at the last bin: window [16, 18], clipped at nbins - 1.
  recs = repeat(12, 9, 0);
  auto side = repeat(3, 7, 0);
  recs.insert(recs.end(), side.begin(), side.end());
  const FrameResult last = estimate_flow(recs, p);
  CHECK(bits(last.flow_x) == bits(((18.0f * 12 + 16.0f * 3) / 15.0f - 9.0f) / 2.0f));
}

TEST_CASE("HF off: the mean of the half-pixel displacements, one rounding", "[estimate]") {
  Params p;
  p.hist_filter = false;
  // sum hx = 1 + 2*12 = 25 over 13 POIs: 12.5 / 13 rounded once to float.
  auto recs = repeat(12, 2, -1);
  recs.push_back(accepted({{1, 0}})[0]);
  const FrameResult r = estimate_flow(recs, p);
  CHECK(bits(r.flow_x) == bits(12.5f / 13.0f));
  CHECK(bits(r.flow_y) == bits(-6.0f / 13.0f));
}

TEST_CASE("quality uses the profile's B even where the grid has fewer points", "[estimate]") {
  Params p;
  p.search_radius = 3;  // 7x7 grid at 64 pixels, but B stays 8
  auto recs = repeat(49, 0, 0);
  CHECK(estimate_flow(recs, p).quality == 49 * 255 / 64);
  auto with_dropped = accepted({}, 5);
  CHECK(estimate_flow(with_dropped, p).meancount == 0);
}

TEST_CASE("gyro compensation: added rotation, threshold and clamp (GC on only)", "[estimate]") {
  Params p;
  p.hist_filter = false;
  const auto recs = repeat(20, 2, 2);  // flow (1, 1)
  const float focal = 16.0f / (4.0f * 6.0f) * 1000.0f;
  GyroSample g{0.5f, 0.02f, 1000};  // x_rate, y_rate, dt_us
  FrameResult off = estimate_flow(recs, p, g);
  CHECK(bits(off.flow_x) == bits(1.0f));  // GC off: the sample is ignored
  p.gyro_comp = true;
  FrameResult on = estimate_flow(recs, p, g);
  CHECK(bits(on.flow_x) == bits(1.0f + 0.02f * (1000.0f / 1000000.0f) * focal));
  // flow_y - 0.5 * 0.001 * 666.67 = 1 - 0.333: inside the clamp.
  CHECK(bits(on.flow_y) == bits(1.0f - 0.5f * (1000.0f / 1000000.0f) * focal));
  g = {0.005f, 100.0f, 1000};  // x below threshold; y far beyond the window: clamp at S + 0.5
  on = estimate_flow(recs, p, g);
  CHECK(bits(on.flow_x) == bits(4.5f));
  CHECK(bits(on.flow_y) == bits(1.0f));
  g = {100.0f, 0.0f, 1000};
  CHECK(bits(estimate_flow(recs, p, g).flow_y) == bits(-4.5f));
}
