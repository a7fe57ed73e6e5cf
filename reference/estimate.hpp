// The frame estimate (SPEC §5): histograms, histogram filter or plain mean, quality, and the
// optional gyro compensation. Shared host code: every backend's records go through this, and
// the GAP8 program's own soft-float estimate is compared against it.
#pragma once
#include <cstdint>
#include <span>

#include "params.hpp"
#include "record.hpp"

namespace pxflow {

// Body rates and frame interval for gyro compensation (used only when Params::gyro_comp).
struct GyroSample {
  float x_rate = 0.0f;  // rad/s
  float y_rate = 0.0f;
  std::uint32_t dt_us = 0;  // time between the two frames
};

// Number of histogram bins for search radius S: 2*(2S+1)+1.
// The largest |hx| or |hy| of a record (2S+1 half-pixel steps); bin hist_reach(S) counts 0.
inline int hist_reach(int S) { return 2 * S + 1; }
inline int hist_bins(int S) { return 2 * hist_reach(S) + 1; }

// Throws std::out_of_range when an accepted record's hx or hy lies outside the histogram
// (|h| > 2S+1): records from a broken kernel or device, which SPEC §3 never produces; the
// message names the record.
FrameResult estimate_flow(std::span<const PoiRecord> records, const Params& p,
                          const GyroSample& gyro = {});

}  // namespace pxflow
