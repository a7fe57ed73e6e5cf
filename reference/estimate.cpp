// Built with -ffp-contract=off (top-level CMakeLists.txt): every float operation below rounds
// once, in the order written, so the result's bits are the same on every host.
#include "estimate.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace pxflow {
namespace {

// HF on: the weighted mean of the five bins around the first maximum, clipped to the histogram.
float filtered_flow(const std::vector<std::uint16_t>& hist, int S) {
  const int nbins = static_cast<int>(hist.size());
  int peak = 0;
  for (int b = 1; b < nbins; ++b)
    if (hist[b] > hist[peak]) peak = b;  // strict: the first maximum wins
  const int lo = peak - 2 < 0 ? 0 : peak - 2;
  const int hi = peak + 2 > nbins - 1 ? nbins - 1 : peak + 2;
  float value = 0.0f;  // accumulated in float, as the firmware does; exact (small integers)
  float weight = 0.0f;
  for (int b = lo; b <= hi; ++b) {
    value += static_cast<float>(b * hist[b]);
    weight += static_cast<float>(hist[b]);
  }
  const float mean_bin = value / weight;  // the one rounding that matters
  return (mean_bin - static_cast<float>(hist_reach(S))) / 2.0f;
}

// GC: adds the rotation seen by the gyro, then clamps to the search window plus half a pixel.
float compensate(float flow, float rate, std::uint32_t dt_us, int S) {
  const float focal_px = 16.0f / (4.0f * 6.0f) * 1000.0f;  // 16 mm lens, 6 um pixels, binning 4
  const float comp = flow + rate * (static_cast<float>(dt_us) / 1000000.0f) * focal_px;
  const float limit = static_cast<float>(S) + 0.5f;
  return comp < -limit ? -limit : (comp > limit ? limit : comp);
}

}  // namespace

FrameResult estimate_flow(std::span<const PoiRecord> records, const Params& p,
                          const GyroSample& gyro) {
  const int S = p.search_radius;
  FrameResult r;
  r.histx.assign(hist_bins(S), 0);
  r.histy.assign(hist_bins(S), 0);
  std::int64_t sum_hx = 0, sum_hy = 0;
  const int reach = hist_reach(S);  // bin 0 holds -reach
  for (const PoiRecord& rec : records) {
    if (rec.status != kAccepted) continue;
    if (std::abs(int{rec.hx}) > reach || std::abs(int{rec.hy}) > reach)
      throw std::out_of_range("record " + std::to_string(&rec - records.data()) +
                              " (x=" + std::to_string(rec.x) + ",y=" + std::to_string(rec.y) +
                              ") has hx=" + std::to_string(rec.hx) +
                              " hy=" + std::to_string(rec.hy) + ", outside the histogram's +-" +
                              std::to_string(reach) + ": no flow can be estimated from it");
    ++r.meancount;
    ++r.histx[rec.hx + reach];
    ++r.histy[rec.hy + reach];
    sum_hx += rec.hx;
    sum_hy += rec.hy;
  }
  if (r.meancount <= p.min_count) return r;  // flow 0, quality 0

  if (p.hist_filter) {
    r.flow_x = filtered_flow(r.histx, S);
    r.flow_y = filtered_flow(r.histy, S);
  } else {
    // sum(hx)/2 = sum(bx + sx/2) is exact in float; the division is the only rounding.
    const float n = static_cast<float>(r.meancount);
    r.flow_x = (static_cast<float>(sum_hx) / 2.0f) / n;
    r.flow_y = (static_cast<float>(sum_hy) / 2.0f) / n;
  }
  if (p.gyro_comp) {
    // Firmware order: rotation about y moves the image along x (added), about x along y
    // (subtracted); each only when the rate is above the 0.01 rad/s threshold.
    if (std::fabs(gyro.y_rate) > 0.01f) r.flow_x = compensate(r.flow_x, gyro.y_rate, gyro.dt_us, S);
    if (std::fabs(gyro.x_rate) > 0.01f)
      r.flow_y = compensate(r.flow_y, -gyro.x_rate, gyro.dt_us, S);
  }
  r.quality = r.meancount * 255 / (p.blocks * p.blocks);
  return r;
}

}  // namespace pxflow
