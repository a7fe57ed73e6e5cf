/* The integer search's outer loop (SPEC §3 step 2), shared by flow_search.c and
 * flow_search_fast.c, which differ only in how they search one row of displacements: prev's
 * block is packed into 16 words, then the rows dy = -S..S are searched in raster order; a
 * strictly smaller SAD replaces (ties keep the first). */
#ifndef PXFLOW_GAP8_SEARCH_RASTER_H
#define PXFLOW_GAP8_SEARCH_RASTER_H

#include "flow_kernel.h"
#include "flow_simd.h"

/* Candidates cand .. cand+n-1 of next (row stride w) against prev's packed block; a SAD strictly
 * smaller than *best replaces it. Returns the candidate of the last replacement, or 0. */
typedef const uint8_t *(*search_row_fn)(const uint32_t *blk, const uint8_t *cand, uint32_t w,
                                        uint32_t n, uint32_t *best);

/* Always inlined, so `row` is a direct call (or inlined) as if written here. */
static inline __attribute__((always_inline)) uint32_t search_raster(
    const flow_ctx *c, const uint8_t *blk, uint32_t x, uint32_t y, int *bx, int *by,
    search_row_fn row_search) {
  const int s = (int)c->search_radius;
  const uint32_t w = c->width;
  uint32_t packed[16];
#pragma GCC unroll 8
  for (int r = 0; r < 8; ++r) {
    packed[2 * r] = ld4(blk + r * w);
    packed[2 * r + 1] = ld4(blk + r * w + 4);
  }
  uint32_t best = 0xFFFFFFFFu;
  for (int dy = -s; dy <= s; ++dy) {
    const uint8_t *row = c->next + (y + dy) * w + x - s;
    const uint8_t *hit = row_search(packed, row, w, (uint32_t)(2 * s + 1), &best);
    if (hit) {
      *bx = (int)(hit - row) - s;
      *by = dy;
    }
  }
  return best;
}

#endif
