/* The eight half-pixel SADs read from precomputed planes h, g, d (local and global variants).
 * h, g, d point at the plane cell of the matched block's top-left pixel; `stride` is the planes'
 * row pitch. Direction k's value at block pixel (c, r) is SPEC §3's table: h(c, r), d(c, r),
 * g(c, r), d(c-1, r), h(c-1, r), d(c-1, r-1), g(c, r-1), d(c, r-1). */
#ifndef PXFLOW_GAP8_HALF_PLANES_H
#define PXFLOW_GAP8_HALF_PLANES_H

#include "flow_simd.h"

static inline void sads_from_planes(const uint8_t *blk, uint32_t w, const uint8_t *h,
                                    const uint8_t *g, const uint8_t *d, int stride,
                                    uint32_t sub[8]) {
  uint32_t acc[8] = {0};
  for (int r = 0; r < 8; ++r) {
    for (int half = 0; half < 8; half += 4) {
      const int at = r * stride + half, above = at - stride;
      const uint32_t a = ld4(blk + r * w + half);
      acc[0] = sad4_acc(acc[0], a, ld4(h + at));
      acc[1] = sad4_acc(acc[1], a, ld4(d + at));
      acc[2] = sad4_acc(acc[2], a, ld4(g + at));
      acc[3] = sad4_acc(acc[3], a, ld4(d + at - 1));
      acc[4] = sad4_acc(acc[4], a, ld4(h + at - 1));
      acc[5] = sad4_acc(acc[5], a, ld4(d + above - 1));
      acc[6] = sad4_acc(acc[6], a, ld4(g + above));
      acc[7] = sad4_acc(acc[7], a, ld4(d + above));
    }
  }
  for (int k = 0; k < 8; ++k) sub[k] = acc[k];
}

#endif
