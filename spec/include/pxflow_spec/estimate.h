/* SPEC §5's frame estimate without gyro compensation, in float as the firmware: the one
 * definition of the freestanding side (dut/'s pxdut_estimate_flow, which the Cortex-M4 firmware
 * runs too, and the GAP8 kernel on its simulated core). reference/estimate.cpp is its readable
 * C++ twin with GC; every device's RESULT is compared with it bit for bit.
 *
 * Build with -ffp-contract=off: each float operation rounds once, in the order written. */
#ifndef PXFLOW_SPEC_ESTIMATE_H
#define PXFLOW_SPEC_ESTIMATE_H

#include <stdint.h>

#include "params.h"
#include "record.h"

typedef struct {
  float flow_x, flow_y; /* pixels per frame */
  int32_t quality, meancount;
} pxflow_estimate;

/* V / Wt over the bins lo..hi of HF's window: the histogram filter's one rounding. */
typedef float (*pxflow_window_mean_fn)(const uint16_t *hist, int lo, int hi);

/* The firmware's way: value and weight accumulated in float (exact: small integers). A kernel
 * may pass its own that gives the same bits (none does today: the GAP8 fast variant brings its
 * whole estimate, kernels/gap8/fast_serial.c). */
static inline float pxflow_window_mean_float(const uint16_t *hist, int lo, int hi) {
  float value = 0.0f, weight = 0.0f;
  for (int b = lo; b <= hi; ++b) {
    value += (float)(b * hist[b]);
    weight += (float)hist[b];
  }
  return value / weight;
}

/* HF on: the weighted mean of the five bins around the first maximum, clipped to the histogram. */
static inline float pxflow_filtered_flow(const uint16_t *hist, int nbins, int s,
                                         pxflow_window_mean_fn window_mean) {
  int peak = 0;
  for (int b = 1; b < nbins; ++b)
    if (hist[b] > hist[peak]) peak = b; /* strict: the first maximum wins */
  const int lo = peak - 2 < 0 ? 0 : peak - 2;
  const int hi = peak + 2 > nbins - 1 ? nbins - 1 : peak + 2;
  return (window_mean(hist, lo, hi) - (float)(2 * s + 1)) / 2.0f;
}

/* The estimate of `pois` records with the parameters p (S, B, HF, MINCOUNT; GC is ignored). */
static inline void pxflow_estimate_flow(const pxflow_poi_record *records, uint32_t pois,
                                        const pxflow_param_block *p,
                                        pxflow_window_mean_fn window_mean, pxflow_estimate *out) {
  const int s = (int)p->search_radius;
  const int nbins = (int)pxflow_hist_bins(p->search_radius);
  uint16_t histx[PXFLOW_MAX_BINS], histy[PXFLOW_MAX_BINS];
  for (int b = 0; b < nbins; ++b) histx[b] = histy[b] = 0;
  int32_t count = 0, sum_hx = 0, sum_hy = 0;
  for (uint32_t n = 0; n < pois; ++n) {
    const pxflow_poi_record *r = &records[n];
    if (r->status != PXFLOW_STATUS_ACCEPTED) continue;
    ++count;
    ++histx[r->hx + 2 * s + 1];
    ++histy[r->hy + 2 * s + 1];
    sum_hx += r->hx;
    sum_hy += r->hy;
  }
  out->meancount = count;
  out->flow_x = out->flow_y = 0.0f;
  out->quality = 0;
  if (count <= (int32_t)p->min_count) return;
  if (p->hist_filter) {
    out->flow_x = pxflow_filtered_flow(histx, nbins, s, window_mean);
    out->flow_y = pxflow_filtered_flow(histy, nbins, s, window_mean);
  } else {
    /* sum(hx)/2 is exact in float; the division by the count is the one rounding. */
    const float n = (float)count;
    out->flow_x = ((float)sum_hx / 2.0f) / n;
    out->flow_y = ((float)sum_hy / 2.0f) / n;
  }
  /* The profile's B, even where the grid has fewer points (SPEC §5). */
  out->quality = count * 255 / (int32_t)(p->blocks * p->blocks);
}

#endif
