/* The grid of SPEC §2, the parameter check of SPEC §1, and one pair's records in grid order. */
#include "m4_flow.h"

#define M4_FLOW_MAX_SIDE 16384u /* reference/params.hpp kMaxFrameSide */

m4_flow_status m4_flow_check(const m4_flow_params *p) {
  if (p->search_radius < 1 || p->search_radius > M4_FLOW_MAX_RADIUS) return M4_FLOW_BAD_RADIUS;
  if (p->blocks < 1 || p->blocks > 255) return M4_FLOW_BAD_BLOCKS;
  if (p->feature_threshold > 65535 || p->sad_threshold > 65535 || p->min_count > 65535 ||
      p->hist_filter > 1)
    return M4_FLOW_BAD_THRESHOLD;
  if (p->width > M4_FLOW_MAX_SIDE || p->height > M4_FLOW_MAX_SIDE) return M4_FLOW_TOO_LARGE;
  /* lo < hi on each axis: side >= 2 (S + 1) + T + 1 */
  const uint32_t min_side = 2 * (p->search_radius + 1) + M4_FLOW_TILE + 1;
  if (p->width < min_side || p->height < min_side) return M4_FLOW_NO_POI;
  return M4_FLOW_OK;
}

uint32_t m4_flow_axis(uint32_t side, const m4_flow_params *p, uint32_t *first, uint32_t *step) {
  /* lo = S+1, hi = side-(S+1)-T, step = (hi-lo)/B + 1 (integer division), coordinates
   * lo, lo+step, ... while < hi: the firmware's loop. Signed, as hi < lo for tiny frames. */
  const int32_t lo = (int32_t)p->search_radius + 1;
  const int32_t hi = (int32_t)side - lo - (int32_t)M4_FLOW_TILE;
  const int32_t st = (hi - lo) / (int32_t)p->blocks + 1;
  *first = (uint32_t)lo;
  *step = st < 1 ? 1u : (uint32_t)st;
  return hi > lo ? (uint32_t)((hi - lo - 1) / st + 1) : 0u;
}

uint32_t m4_flow_poi_count(const m4_flow_params *p) {
  uint32_t first, step;
  return m4_flow_axis(p->width, p, &first, &step) * m4_flow_axis(p->height, p, &first, &step);
}

void m4_flow_frame(const m4_flow_params *p, const uint8_t *prev, const uint8_t *next,
                   m4_flow_record *records) {
  uint32_t x0, xstep, y0, ystep;
  const uint32_t nx = m4_flow_axis(p->width, p, &x0, &xstep);
  const uint32_t ny = m4_flow_axis(p->height, p, &y0, &ystep);
  for (uint32_t j = 0; j < ny; ++j)   /* rows outer, */
    for (uint32_t i = 0; i < nx; ++i) /* columns inner: the record index is grid order */
      m4_flow_poi(p, prev, next, x0 + i * xstep, y0 + j * ystep, records++);
}
