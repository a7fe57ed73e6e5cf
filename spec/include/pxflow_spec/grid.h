/* SPEC §2's grid of points of interest, per axis: the one definition of the freestanding
 * kernels (reference/grid.cpp is its readable C++ twin; both are checked by every backend's
 * records, which carry x and y). */
#ifndef PXFLOW_SPEC_GRID_H
#define PXFLOW_SPEC_GRID_H

#include <stdint.h>

#include "params.h"

/* One axis: coordinates first, first + step, ..., count of them. */
typedef struct {
  uint32_t first, step, count;
} pxflow_grid_axis;

/* lo = S+1, hi = side-(S+1)-T, step = (hi-lo)/B + 1 (integer division, as the firmware), and the
 * values lo + k*step that are < hi: the firmware's loop `for (c = lo; c < hi; c += step)`. Kept
 * exactly, even where it gives fewer than B points (S = 3, 6, 7 at 64x64). Signed, since hi < lo
 * for a side too small; count is then 0 (and step 1). B = 0 gives no point rather than a
 * division by zero. */
static inline pxflow_grid_axis pxflow_grid_axis_of(uint32_t side, uint32_t search_radius,
                                                   uint32_t blocks) {
  pxflow_grid_axis a = {search_radius + 1u, 1u, 0u};
  const int32_t lo = (int32_t)search_radius + 1;
  const int32_t hi = (int32_t)side - lo - (int32_t)PXFLOW_TILE;
  if (hi <= lo || blocks == 0u) return a;
  a.step = (uint32_t)((hi - lo) / (int32_t)blocks + 1);
  a.count = (uint32_t)(hi - lo - 1) / a.step + 1u;
  return a;
}

/* The POIs of a frame: the records one pair produces, row by row. */
static inline uint32_t pxflow_poi_count(const pxflow_param_block *p) {
  return pxflow_grid_axis_of(p->width, p->search_radius, p->blocks).count *
         pxflow_grid_axis_of(p->height, p->search_radius, p->blocks).count;
}

#endif
