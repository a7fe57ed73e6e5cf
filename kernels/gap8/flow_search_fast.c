/* The integer search of the "fast" variant (beyond the paper): prev's 8x8 block is loaded once
 * per POI into 16 registers and reused by all (2S+1)^2 candidates, so each candidate loads only
 * next's 16 words: half the loads of flow_search.c, same SADs in the same order (bit-exact). */
#include "flow_kernel.h"
#include "flow_simd.h"

uint32_t flow_integer_search(const flow_ctx *c, const uint8_t *blk, uint32_t x, uint32_t y, int *bx,
                             int *by) {
  const int s = (int)c->search_radius;
  const uint32_t w = c->width;
  uint32_t a[16]; /* constant indices after unrolling: kept in registers */
#pragma GCC unroll 8
  for (int r = 0; r < 8; ++r) {
    a[2 * r] = ld4(blk + r * w);
    a[2 * r + 1] = ld4(blk + r * w + 4);
  }
  uint32_t best = 0xFFFFFFFFu;
  for (int dy = -s; dy <= s; ++dy) {
    const uint8_t *row = c->next + (y + dy) * w + x - s;
    for (int dx = -s; dx <= s; ++dx, ++row) {
      uint32_t sad = 0;
      const uint8_t *b = row;
#pragma GCC unroll 8
      for (int r = 0; r < 8; ++r, b += w) {
        sad = sad4_acc(sad, a[2 * r], ld4(b));
        sad = sad4_acc(sad, a[2 * r + 1], ld4(b + 4));
      }
      if (sad < best) {
        best = sad;
        *bx = dx;
        *by = dy;
      }
    }
  }
  return best;
}
