/* SPEC §3 on the Cortex-M4, shaped like the firmware's compute_flow: the feature test
 * (compute_diff), the integer search (compute_sad_8x8 for every candidate, strictly smaller
 * replaces) and the half-pixel refinement (compute_subpixel: 12 UHADD8 and 8 USADA8 per group of
 * 4 pixels, the values made on the spot, the "original" variant of SPEC §6). Every 4-byte SAD is
 * one USAD8 or USADA8, every 4-pixel floor average one UHADD8 (m4_simd.h). Coordinates and
 * offsets are 32-bit (the firmware's uint16_t offsets would wrap beyond 64 KiB frames). */
#include <stddef.h>

#include "m4_flow.h"
#include "m4_simd.h"

/* Half-pixel step (sx, sy) of direction k (SPEC §3's table); k = 8 is the integer match. */
static const int8_t kStepX[PXFLOW_DIRECTIONS + 1] = PXFLOW_STEP_X_TABLE;
static const int8_t kStepY[PXFLOW_DIRECTIONS + 1] = PXFLOW_STEP_Y_TABLE;

/* Four pixels of a column packed into a word, as the firmware's col1..col4 (its byte order is the
 * reverse; lanes are independent, so the SAD is the same). */
static uint32_t column4(const uint8_t *q, uint32_t w) {
  return (uint32_t)q[0] | (uint32_t)q[w] << 8 | (uint32_t)q[2 * w] << 16 | (uint32_t)q[3 * w] << 24;
}

/* compute_diff: the 24 neighbour differences of the block's central 4x4 (SPEC §3 step 1), as 3
 * row and 3 column USADA8. At most 24 x 255 = 6,120. */
static uint32_t feature(const uint8_t *blk, uint32_t w) {
  const uint8_t *q = blk + 2 * w + 2;
  uint32_t acc = m4_sad4(m4_ld4(q), m4_ld4(q + w));
  acc = m4_sad4_acc(m4_ld4(q + w), m4_ld4(q + 2 * w), acc);
  acc = m4_sad4_acc(m4_ld4(q + 2 * w), m4_ld4(q + 3 * w), acc);
  const uint32_t c0 = column4(q, w), c1 = column4(q + 1, w);
  const uint32_t c2 = column4(q + 2, w), c3 = column4(q + 3, w);
  acc = m4_sad4_acc(c0, c1, acc);
  acc = m4_sad4_acc(c1, c2, acc);
  return m4_sad4_acc(c2, c3, acc);
}

/* compute_sad_8x8: 16 USAD8/USADA8 over two 8x8 blocks of stride w. At most 16,320. */
static uint32_t sad_8x8(const uint8_t *a, const uint8_t *b, uint32_t w) {
  uint32_t acc = 0;
  for (uint32_t r = 0; r < 8; ++r, a += w, b += w) {
    acc = m4_sad4_acc(m4_ld4(a), m4_ld4(b), acc);
    acc = m4_sad4_acc(m4_ld4(a + 4), m4_ld4(b + 4), acc);
  }
  return acc;
}

/* SPEC §3 step 2: dy outer, dx inner, both -S..S; only a strictly smaller SAD replaces, so a tie
 * keeps the first candidate in raster order. */
static uint32_t integer_search(const uint8_t *blk, const uint8_t *next, uint32_t x, uint32_t y,
                               uint32_t w, int s, int *bx, int *by) {
  uint32_t best = PXFLOW_SAD_SENTINEL;
  *bx = *by = 0;
  for (int dy = -s; dy <= s; ++dy) {
    const uint8_t *row = next + (size_t)((int)y + dy) * w + x;
    for (int dx = -s; dx <= s; ++dx) {
      const uint32_t d = sad_8x8(blk, row + dx, w);
      if (d < best) {
        best = d;
        *bx = dx;
        *by = dy;
      }
    }
  }
  return best;
}

/* compute_subpixel for the 4 pixels at column offset c of row r: `a` is prev's word, `p` points
 * at P(c, r) of next (the matched block's pixel), w is the stride. The s values are the
 * firmware's: s0 = h(c, r), s1 = h(c, r+1), s2 = g(c, r), s3 = h(c-1, r+1), s4 = h(c-1, r),
 * s5 = h(c-1, r-1), s6 = g(c, r-1), s7 = h(c, r-1); the diagonals are floor averages of two
 * horizontal averages, each floored (SPEC §3: d(u, v) = avg(h(u, v), h(u, v+1))):
 * t1 = d(c, r), t3 = d(c-1, r), t5 = d(c-1, r-1), t7 = d(c, r-1). Directions 0..7 are then
 * s0, t1, s2, t3, s4, t5, s6, t7, exactly SPEC §3's table. */
static void subpixel_group(uint32_t a, const uint8_t *p, uint32_t w, uint32_t acc[8]) {
  const uint8_t *up = p - w, *down = p + w;
  const uint32_t centre = m4_ld4(p), below = m4_ld4(down), above = m4_ld4(up);
  const uint32_t s0 = m4_avg4(centre, m4_ld4(p + 1));
  const uint32_t s1 = m4_avg4(below, m4_ld4(down + 1));
  const uint32_t s2 = m4_avg4(centre, below);
  const uint32_t s3 = m4_avg4(below, m4_ld4(down - 1));
  const uint32_t s4 = m4_avg4(centre, m4_ld4(p - 1));
  const uint32_t s5 = m4_avg4(above, m4_ld4(up - 1));
  const uint32_t s6 = m4_avg4(centre, above);
  const uint32_t s7 = m4_avg4(above, m4_ld4(up + 1));
  const uint32_t t1 = m4_avg4(s0, s1);
  const uint32_t t3 = m4_avg4(s3, s4);
  const uint32_t t5 = m4_avg4(s4, s5);
  const uint32_t t7 = m4_avg4(s7, s0);
  acc[0] = m4_sad4_acc(a, s0, acc[0]);
  acc[1] = m4_sad4_acc(a, t1, acc[1]);
  acc[2] = m4_sad4_acc(a, s2, acc[2]);
  acc[3] = m4_sad4_acc(a, t3, acc[3]);
  acc[4] = m4_sad4_acc(a, s4, acc[4]);
  acc[5] = m4_sad4_acc(a, t5, acc[5]);
  acc[6] = m4_sad4_acc(a, s6, acc[6]);
  acc[7] = m4_sad4_acc(a, t7, acc[7]);
}

/* The eight half-pixel SADs of prev's block against the neighbourhood of next's matched block
 * (top-left `m`): 8 rows of two 4-pixel groups. Reads rows -1..8 and columns -1..8 around m. */
static void subpixel(const uint8_t *blk, const uint8_t *m, uint32_t w, uint32_t acc[8]) {
  for (int k = 0; k < 8; ++k) acc[k] = 0;
  for (uint32_t r = 0; r < 8; ++r, blk += w, m += w) {
    subpixel_group(m4_ld4(blk), m, w, acc);
    subpixel_group(m4_ld4(blk + 4), m + 4, w, acc);
  }
}

void m4_flow_poi(const pxflow_param_block *p, const uint8_t *prev, const uint8_t *next, uint32_t x,
                 uint32_t y, pxflow_poi_record *rec) {
  const uint32_t w = p->width;
  const uint8_t *blk = prev + (size_t)y * w + x;
  pxflow_poi_record r = {0}; /* SPEC §4: undefined fields and padding are 0 */
  r.x = (uint16_t)x;
  r.y = (uint16_t)y;
  r.dir = PXFLOW_DIR_NONE;
  r.feature = (uint16_t)feature(blk, w);
  if (r.feature >= p->feature_threshold) {
    int bx, by;
    const uint32_t best = integer_search(blk, next, x, y, w, (int)p->search_radius, &bx, &by);
    r.dx = (int8_t)bx;
    r.dy = (int8_t)by;
    r.sad = (uint16_t)best;
    r.status = PXFLOW_STATUS_REJECTED;
    if (best < p->sad_threshold) {
      uint32_t acc[8];
      subpixel(blk, next + (size_t)(y + (uint32_t)by) * w + (x + (uint32_t)bx), w, acc);
      /* From (best, dir 8), k = 0..7, strictly smaller replaces: ties keep the lower k and a
       * half step wins only when strictly better than the integer match. */
      uint32_t min = best;
      uint32_t dir = PXFLOW_DIR_NONE;
      for (uint32_t k = 0; k < 8; ++k) {
        r.sub[k] = (uint16_t)acc[k];
        if (acc[k] < min) {
          min = acc[k];
          dir = k;
        }
      }
      r.status = PXFLOW_STATUS_ACCEPTED;
      r.dir = (uint8_t)dir;
      r.hx = (int8_t)(2 * bx + kStepX[dir]);
      r.hy = (int8_t)(2 * by + kStepY[dir]);
    }
  }
  *rec = r;
}
