/* Variant "local": per accepted POI, the planes h, g, d over the matched block plus a one-pixel
 * border (10x10, block coordinates -1..8) once, four cells at a time, then the eight directions
 * read them (the paper's 300 interpolations per POI). The planes live on the core's stack. */
#include "flow_kernel.h"
#include "half_planes.h"

const uint32_t variant_planes = 0;

enum { kSide = 10, kPitch = 12 }; /* 10 cells per row, padded to three words */

void variant_prepare(const flow_ctx *c, uint32_t core) {
  (void)c;
  (void)core;
}

void variant_half_sads(const flow_ctx *c, const uint8_t *blk, uint32_t mx, uint32_t my,
                       uint32_t sub[8]) {
  const uint32_t w = c->width;
  uint32_t hw[kSide * kPitch / 4], gw[kSide * kPitch / 4], dw[kSide * kPitch / 4];
  /* Row v of the planes holds block row v-1, word q its cells u = 4q-1 .. 4q+2. The cells of
   * the far border (u or v = 8, 9, 10) read pixels no direction needs: computed, never read. */
  const uint8_t *p = c->next + (my - 1) * w + mx - 1;
  for (int v = 0; v < kSide; ++v, p += w) {
    for (int q = 0; q < kPitch / 4; ++q) {
      const uint32_t a = ld4(p + 4 * q);
      hw[v * 3 + q] = avg4(a, ld4(p + 4 * q + 1));
      gw[v * 3 + q] = avg4(a, ld4(p + 4 * q + w));
    }
  }
  for (int v = 0; v < kSide - 1; ++v)
    for (int q = 0; q < kPitch / 4; ++q) dw[v * 3 + q] = avg4(hw[v * 3 + q], hw[v * 3 + 3 + q]);
  for (int q = 0; q < kPitch / 4; ++q) dw[(kSide - 1) * 3 + q] = 0; /* never read */
  /* Cell (0, 0) of the block is row 1, byte 1. */
  const int origin = kPitch + 1;
  sads_from_planes(blk, w, (const uint8_t *)hw + origin, (const uint8_t *)gw + origin,
                   (const uint8_t *)dw + origin, kPitch, sub);
}
