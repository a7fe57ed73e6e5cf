/* SPEC §5 on core 0 after the join: histograms of the half-pixel displacements, then the
 * histogram filter or the plain mean, in float. The cores have no FPU: every float operation is
 * a libgcc soft-float call, correctly rounded, so the bits match the host's estimate_flow (both
 * built with -ffp-contract=off). */
#include "flow_kernel.h"

/* V / Wt over the bins lo..hi, accumulated in float as the firmware does. Weak: the fast variant
 * sums in integers and converts once (flow_kernel.h). */
__attribute__((weak)) float flow_window_mean(const uint16_t *hist, int lo, int hi) {
  float value = 0.0f, weight = 0.0f;
  for (int b = lo; b <= hi; ++b) {
    value += (float)(b * hist[b]);
    weight += (float)hist[b];
  }
  return value / weight;
}

/* HF on: the weighted mean of the five bins around the first maximum, clipped to the histogram. */
static float filtered_flow(const uint16_t *hist, int nbins, int s) {
  int peak = 0;
  for (int b = 1; b < nbins; ++b)
    if (hist[b] > hist[peak]) peak = b; /* strict: the first maximum wins */
  const int lo = peak - 2 < 0 ? 0 : peak - 2;
  const int hi = peak + 2 > nbins - 1 ? nbins - 1 : peak + 2;
  return (flow_window_mean(hist, lo, hi) - (float)(2 * s + 1)) / 2.0f;
}

void flow_estimate(const pxflow_gap8_record *records, uint32_t pois, const pxflow_gap8_params *p,
                   pxflow_gap8_result *out) {
  const int s = (int)p->search_radius;
  const int nbins = 2 * (2 * s + 1) + 1;
  uint16_t histx[PXFLOW_GAP8_MAX_BINS], histy[PXFLOW_GAP8_MAX_BINS];
  for (int b = 0; b < nbins; ++b) histx[b] = histy[b] = 0;
  int count = 0, sum_hx = 0, sum_hy = 0;
  for (uint32_t n = 0; n < pois; ++n) {
    const pxflow_gap8_record *r = &records[n];
    if (r->status != PXFLOW_GAP8_ACCEPTED) continue;
    ++count;
    ++histx[r->hx + 2 * s + 1];
    ++histy[r->hy + 2 * s + 1];
    sum_hx += r->hx;
    sum_hy += r->hy;
  }
  out->meancount = count;
  out->flow_x = out->flow_y = 0.0f;
  out->quality = 0;
  if (count <= (int)p->min_count) return;
  if (p->hist_filter) {
    out->flow_x = filtered_flow(histx, nbins, s);
    out->flow_y = filtered_flow(histy, nbins, s);
  } else {
    /* sum(hx)/2 is exact in float; the division by the count is the one rounding. */
    const float n = (float)count;
    out->flow_x = ((float)sum_hx / 2.0f) / n;
    out->flow_y = ((float)sum_hy / 2.0f) / n;
  }
  out->quality = count * 255 / (int)(p->blocks * p->blocks);
}
