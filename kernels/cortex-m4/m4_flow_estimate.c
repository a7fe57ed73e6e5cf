/* SPEC §5 on the Cortex-M4F's FPU (single precision, fpv4-sp-d16): histograms of the half-pixel
 * displacements, then the histogram filter or the plain mean. Built with -ffp-contract=off, so
 * no VFMA/VMLA fuses a multiply and an add: every operation below rounds once, in the order
 * written, like reference/estimate.cpp on the host, and the bits agree. The start-up code sets
 * FPSCR to 0 (round to nearest even, no flush-to-zero, no default NaN: the host's IEEE-754
 * behaviour; DDI 0403E, A2.5 "The optional Floating-point extension", FPSCR), as its reset value
 * is not relied on. */
#include "m4_flow.h"

/* HF on: the weighted mean of the five bins around the first maximum, clipped to the histogram;
 * V and Wt accumulated in float, as the firmware does (exact: small integers). */
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
  const float mean_bin = value / weight; /* the one rounding that matters */
  return (mean_bin - (float)(2 * s + 1)) / 2.0f;
}

void m4_flow_estimate(const m4_flow_record *records, uint32_t count, const m4_flow_params *p,
                      m4_flow_result *out) {
  const int s = (int)p->search_radius;
  const int nbins = 2 * (2 * s + 1) + 1;
  uint16_t histx[M4_FLOW_MAX_BINS], histy[M4_FLOW_MAX_BINS];
  for (int b = 0; b < nbins; ++b) histx[b] = histy[b] = 0;
  int32_t accepted = 0, sum_hx = 0, sum_hy = 0;
  for (uint32_t n = 0; n < count; ++n) {
    const m4_flow_record *r = &records[n];
    if (r->status != M4_FLOW_ACCEPTED) continue;
    ++accepted;
    ++histx[r->hx + 2 * s + 1];
    ++histy[r->hy + 2 * s + 1];
    sum_hx += r->hx;
    sum_hy += r->hy;
  }
  out->meancount = accepted;
  out->flow_x = out->flow_y = 0.0f;
  out->quality = 0;
  if (accepted <= (int32_t)p->min_count) return; /* flow 0, quality 0 */
  if (p->hist_filter) {
    out->flow_x = filtered_flow(histx, nbins, s);
    out->flow_y = filtered_flow(histy, nbins, s);
  } else {
    /* sum(hx)/2 = sum(bx + sx/2) is exact in float; the division by the count is the one
     * rounding. */
    const float n = (float)accepted;
    out->flow_x = ((float)sum_hx / 2.0f) / n;
    out->flow_y = ((float)sum_hy / 2.0f) / n;
  }
  /* the profile's B, even where the grid has fewer points */
  out->quality = accepted * 255 / (int32_t)(p->blocks * p->blocks);
}
