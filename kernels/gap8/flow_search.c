/* The integer search of SPEC §3 step 2 as the firmware writes it: for each candidate, the 8x8
 * SAD reloads both blocks (16 words of prev, 16 of next). Used by the paper's three variants. */
#include "flow_kernel.h"
#include "flow_simd.h"

/* 8x8 SAD, two 4-byte halves per row, as the firmware's compute_sad_8x8. */
static uint32_t sad8x8(const uint8_t *a, const uint8_t *b, uint32_t w) {
  uint32_t acc = 0;
#pragma GCC unroll 8
  for (int r = 0; r < 8; ++r) {
    acc = sad4_acc(acc, ld4(a), ld4(b));
    acc = sad4_acc(acc, ld4(a + 4), ld4(b + 4));
    a += w;
    b += w;
  }
  return acc;
}

/* Raster order over dy, dx in -S..S; a strictly smaller SAD replaces (ties keep the first). */
uint32_t flow_integer_search(const flow_ctx *c, const uint8_t *blk, uint32_t x, uint32_t y, int *bx,
                             int *by) {
  const int s = (int)c->search_radius;
  const uint32_t w = c->width;
  uint32_t best = 0xFFFFFFFFu;
  for (int dy = -s; dy <= s; ++dy) {
    const uint8_t *row = c->next + (y + dy) * w + x;
    for (int dx = -s; dx <= s; ++dx) {
      const uint32_t sad = sad8x8(blk, row + dx, w);
      if (sad < best) {
        best = sad;
        *bx = dx;
        *by = dy;
      }
    }
  }
  return best;
}
