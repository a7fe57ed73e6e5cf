/* SPEC §2's grid and §5's frame estimate, as the device computes them. Built with
 * -ffp-contract=off: each float operation rounds once, in the order written, so the bits are the
 * host's (reference/estimate.cpp does the same operations in the same order). */
#include "pxdut.h"

uint32_t pxdut_grid_axis(uint32_t side, const pxdut_params *p, uint16_t *coords) {
  const int32_t lo = (int32_t)p->search_radius + 1;
  const int32_t hi = (int32_t)side - lo - (int32_t)p->tile;
  if (hi <= lo || p->blocks == 0) return 0;
  const int32_t step = (hi - lo) / (int32_t)p->blocks + 1;
  uint32_t n = 0;
  for (int32_t c = lo; c < hi; c += step) {
    if (coords) coords[n] = (uint16_t)c;
    ++n;
  }
  return n;
}

uint32_t pxdut_poi_count(const pxdut_params *p) {
  return pxdut_grid_axis(p->width, p, 0) * pxdut_grid_axis(p->height, p, 0);
}

/* HF on: the weighted mean of the five bins around the first maximum, clipped to the histogram;
 * value and weight accumulated in float as the firmware does (exact: small integers). */
static float filtered_flow(const uint16_t *hist, int nbins, int s) {
  int peak = 0;
  for (int b = 1; b < nbins; ++b)
    if (hist[b] > hist[peak]) peak = b; /* strict: the first maximum wins */
  const int lo = peak - 2 < 0 ? 0 : peak - 2;
  const int hi = peak + 2 > nbins - 1 ? nbins - 1 : peak + 2;
  float value = 0.0f, weight = 0.0f;
  for (int b = lo; b <= hi; ++b) {
    value += (float)(b * hist[b]);
    weight += (float)hist[b];
  }
  const float mean_bin = value / weight;
  return (mean_bin - (float)(2 * s + 1)) / 2.0f;
}

#define PXDUT_MAX_BINS 127 /* 2*(2S+1)+1 for S = 31 */

void pxdut_estimate_flow(const pxdut_record *records, uint32_t pois, const pxdut_params *p,
                         pxdut_estimate *out) {
  const int s = (int)p->search_radius;
  const int nbins = 2 * (2 * s + 1) + 1;
  uint16_t histx[PXDUT_MAX_BINS], histy[PXDUT_MAX_BINS];
  for (int b = 0; b < nbins; ++b) histx[b] = histy[b] = 0;
  int32_t count = 0, sum_hx = 0, sum_hy = 0;
  for (uint32_t n = 0; n < pois; ++n) {
    const pxdut_record *r = &records[n];
    if (r->status != 2) continue;
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
    out->flow_x = filtered_flow(histx, nbins, s);
    out->flow_y = filtered_flow(histy, nbins, s);
  } else {
    /* sum(hx)/2 is exact in float; the division by the count is the one rounding. */
    const float n = (float)count;
    out->flow_x = ((float)sum_hx / 2.0f) / n;
    out->flow_y = ((float)sum_hy / 2.0f) / n;
  }
  out->quality = count * 255 / (int32_t)(p->blocks * p->blocks);
}
