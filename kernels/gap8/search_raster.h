/* The integer search's outer loop (SPEC §3 step 2), shared by flow_search.c and
 * flow_search_fast.c, which differ only in how they search one row of displacements.
 *
 * No branch in a hardware loop: the candidates of one row are a hardware loop, and RI5CY's
 * hardware loops must not hold branches or jumps (CV32E40P user manual, "Hardware Loop
 * constraints": no jump or branch in the body, the loop entered only at its start; RI5CY user
 * manual rev. 4.4 forbids a branch or jump as the last instruction and says nothing of the rest,
 * so we keep the stricter rule). So a row keeps its best candidate without a branch: each
 * candidate's SAD is accumulated scaled by 64 (the .sc dot product's scalar is 64 instead of 1)
 * on top of its index in the row, key = 64 * SAD + (dx + S), and p.minu keeps the smallest key:
 * the smallest SAD, and among equal SADs the smallest dx, the first in raster order. The index
 * fits below 64 because 2S + 1 <= 63 (S <= 31, SPEC §1); the key stays below 2^21. Across rows
 * (plain C, no hardware loop) a row's best replaces only on a strictly smaller SAD, so ties keep
 * the first row: SPEC's raster order and tie rule. */
#ifndef PXFLOW_GAP8_SEARCH_RASTER_H
#define PXFLOW_GAP8_SEARCH_RASTER_H

#include "flow_kernel.h"
#include "flow_simd.h"

/* A candidate's key: 64 * SAD + its index in the row. */
enum { kKeyShift = 6, kKeyScale = 1 << kKeyShift };

/* Candidates row .. row+n-1 of next (row stride w) against prev's packed block: the smallest
 * key of the row (0xFFFFFFFF when n = 0). */
typedef uint32_t (*search_row_fn)(const uint32_t *blk, const uint8_t *row, uint32_t w, uint32_t n);

/* Always inlined, so `row` is a direct call (or inlined) as if written here. */
static inline __attribute__((always_inline)) uint32_t search_raster(const flow_ctx *c,
                                                                    const uint8_t *blk, uint32_t x,
                                                                    uint32_t y, int *bx, int *by,
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
    const uint32_t key = row_search(packed, row, w, (uint32_t)(2 * s + 1));
    const uint32_t sad = key >> kKeyShift;
    if (sad < best) {
      best = sad;
      *bx = (int)(key & (kKeyScale - 1)) - s;
      *by = dy;
    }
  }
  return best;
}

#endif
