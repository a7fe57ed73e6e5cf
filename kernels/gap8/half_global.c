/* Variant "global": before any matching, the team computes the planes h, g, d of the whole next
 * frame into L1 (W*H*3 interpolations, rows split over the cores round robin), then each
 * accepted POI only reads them. The planes' last column (h) and row (g, d) would need pixels
 * beyond the frame: they are computed from the buffers' slack and never read (SPEC §3). */
#include <pmsis.h>

#include "flow_kernel.h"
#include "half_planes.h"

const uint32_t variant_planes = 3;

/* One plane row from `src` rows (y, y+1): word-wide, then the W % 4 tail pixel by pixel, so
 * that no core writes into a row another core owns. */
static void average_row(uint8_t *dst, const uint8_t *a, const uint8_t *b, uint32_t w) {
  uint32_t x = 0;
  for (; x + 4 <= w; x += 4) st4(dst + x, avg4(ld4(a + x), ld4(b + x)));
  for (; x < w; ++x) dst[x] = (uint8_t)((a[x] + b[x]) >> 1);
}

void variant_prepare(const flow_ctx *c, uint32_t core) {
  const uint32_t w = c->width, h = c->height;
  uint8_t *hp = c->planes[0], *gp = c->planes[1], *dp = c->planes[2];
  for (uint32_t y = core; y < h; y += c->cores) {
    const uint8_t *row = c->next + y * w;
    average_row(hp + y * w, row, row + 1, w); /* h(x, y) = avg(P(x, y), P(x+1, y)) */
    average_row(gp + y * w, row, row + w, w); /* g(x, y) = avg(P(x, y), P(x, y+1)) */
  }
  pi_cl_team_barrier(); /* d reads h of the next row, which another core may own */
  for (uint32_t y = core; y < h; y += c->cores)
    average_row(dp + y * w, hp + y * w, hp + (y + 1) * w, w);
  pi_cl_team_barrier();
}

void variant_half_sads(const flow_ctx *c, const uint8_t *blk, uint32_t mx, uint32_t my,
                       uint32_t sub[8]) {
  const uint32_t w = c->width, at = my * w + mx;
  sads_from_planes(blk, w, c->planes[0] + at, c->planes[1] + at, c->planes[2] + at, (int)w, sub);
}
