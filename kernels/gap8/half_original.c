/* Variant "original": the firmware's compute_subpixel. For each 4-pixel group of each block
 * row, the eight directions' values are interpolated on the spot from next (8 horizontal and
 * vertical averages, 4 diagonals as averages of two horizontal ones), then eight SADs. Shared
 * values are recomputed by every direction and every POI: 768 interpolations per POI. */
#include "flow_kernel.h"
#include "flow_simd.h"

const uint32_t variant_planes = 0;

void variant_prepare(const flow_ctx *c, uint32_t core) {
  (void)c;
  (void)core;
}

void variant_half_sads(const flow_ctx *c, const uint8_t *blk, uint32_t mx, uint32_t my,
                       uint32_t sub[8]) {
  const uint32_t w = c->width;
  const uint8_t *match = c->next + my * w + mx;
  uint32_t acc[8] = {0};
  for (int r = 0; r < 8; ++r) {
    for (int half = 0; half < 8; half += 4) {
      const uint8_t *p0 = match + r * w + half; /* P(c, r) for the four pixels */
      const uint8_t *up = p0 - w, *dn = p0 + w;
      const uint32_t s0 = avg4(ld4(p0), ld4(p0 + 1)); /* h(c, r) */
      const uint32_t s1 = avg4(ld4(dn), ld4(dn + 1)); /* h(c, r+1) */
      const uint32_t s2 = avg4(ld4(p0), ld4(dn));     /* g(c, r) */
      const uint32_t s3 = avg4(ld4(dn), ld4(dn - 1)); /* h(c-1, r+1) */
      const uint32_t s4 = avg4(ld4(p0), ld4(p0 - 1)); /* h(c-1, r) */
      const uint32_t s5 = avg4(ld4(up), ld4(up - 1)); /* h(c-1, r-1) */
      const uint32_t s6 = avg4(ld4(p0), ld4(up));     /* g(c, r-1) */
      const uint32_t s7 = avg4(ld4(up), ld4(up + 1)); /* h(c, r-1) */
      const uint32_t a = ld4(blk + r * w + half);
      acc[0] = sad4_acc(acc[0], a, s0);
      acc[1] = sad4_acc(acc[1], a, avg4(s0, s1)); /* d(c, r) */
      acc[2] = sad4_acc(acc[2], a, s2);
      acc[3] = sad4_acc(acc[3], a, avg4(s3, s4)); /* d(c-1, r) */
      acc[4] = sad4_acc(acc[4], a, s4);
      acc[5] = sad4_acc(acc[5], a, avg4(s4, s5)); /* d(c-1, r-1) */
      acc[6] = sad4_acc(acc[6], a, s6);
      acc[7] = sad4_acc(acc[7], a, avg4(s7, s0)); /* d(c, r-1) */
    }
  }
  for (int k = 0; k < 8; ++k) sub[k] = acc[k];
}
