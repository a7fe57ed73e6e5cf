/* The portable C99 kernel of SPEC §3-§4 in the PX4FLOW firmware's shape: the 8x8 block is 16
 * words (two 4-pixel halves per row) and every pixel operation is one of the firmware's 4-byte
 * primitives (SPEC §7), written here in plain C so that any 32-bit core runs it; a port with
 * USAD8/USADA8/UHADD8 (Cortex-M4) swaps the three functions below for its intrinsics. */
#include "pxdut.h"

/* Four pixels from any address, little-endian lanes (the lanes are independent: byte order
 * never changes a result). */
static uint32_t load4(const uint8_t *p) {
  return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* USADA8: acc + sum over the four bytes of |a_i - b_i|. */
static uint32_t usada8(uint32_t a, uint32_t b, uint32_t acc) {
  for (int lane = 0; lane < 32; lane += 8) {
    const int32_t d = (int32_t)((a >> lane) & 0xFFu) - (int32_t)((b >> lane) & 0xFFu);
    acc += (uint32_t)(d < 0 ? -d : d);
  }
  return acc;
}

/* UHADD8: per byte floor((a + b) / 2) with a 9-bit intermediate, carry-free (SPEC §7). */
static uint32_t uhadd8(uint32_t a, uint32_t b) { return (a & b) + (((a ^ b) & 0xFEFEFEFEu) >> 1); }

typedef struct {
  uint32_t w[16]; /* row r: w[2r] = columns 0..3, w[2r+1] = columns 4..7 */
} block_words;

static void load_block(const uint8_t *blk, uint32_t stride, block_words *b) {
  for (uint32_t r = 0; r < 8; ++r) {
    b->w[2 * r] = load4(blk + r * stride);
    b->w[2 * r + 1] = load4(blk + r * stride + 4);
  }
}

/* The firmware's compute_diff: three row and three column 4-byte differences of the central 4x4
 * (24 absolute differences). */
static uint32_t feature(const uint8_t *blk, uint32_t w) {
  const uint8_t *q = blk + 2 * w + 2;
  uint32_t col[4];
  for (int c = 0; c < 4; ++c)
    col[c] = (uint32_t)q[c] | (uint32_t)q[w + c] << 8 | (uint32_t)q[2 * w + c] << 16 |
             (uint32_t)q[3 * w + c] << 24;
  uint32_t acc = 0;
  for (uint32_t r = 0; r < 3; ++r) acc = usada8(load4(q + r * w), load4(q + (r + 1) * w), acc);
  for (int c = 0; c < 3; ++c) acc = usada8(col[c], col[c + 1], acc);
  return acc;
}

/* 8x8 SAD of the block against the candidate whose top-left pixel is `cand` (16 USADA8). */
static uint32_t block_sad(const block_words *b, const uint8_t *cand, uint32_t w) {
  uint32_t acc = 0;
  for (uint32_t r = 0; r < 8; ++r) {
    acc = usada8(b->w[2 * r], load4(cand + r * w), acc);
    acc = usada8(b->w[2 * r + 1], load4(cand + r * w + 4), acc);
  }
  return acc;
}

/* The firmware's compute_subpixel: for each 4-pixel group of each block row, P around the match
 * (rows r-1, r, r+1; columns c-1 .. c+4), the eight directions' values as floor averages (the
 * diagonal is the average of two horizontal averages, SPEC §3), then eight USADA8. */
static void half_sads(const block_words *b, const uint8_t *match, uint32_t w, uint32_t sub[8]) {
  for (int k = 0; k < 8; ++k) sub[k] = 0;
  for (uint32_t r = 0; r < 8; ++r) {
    for (uint32_t half = 0; half < 2; ++half) {
      const uint8_t *pp = match + r * w + 4 * half; /* P(c, r), c = 4 * half */
      const uint32_t a = b->w[2 * r + half];
      const uint32_t h0 = uhadd8(load4(pp), load4(pp + 1));          /* h(c, r) */
      const uint32_t h4 = uhadd8(load4(pp - 1), load4(pp));          /* h(c-1, r) */
      const uint32_t hn0 = uhadd8(load4(pp + w), load4(pp + w + 1)); /* h(c, r+1) */
      const uint32_t hn4 = uhadd8(load4(pp + w - 1), load4(pp + w)); /* h(c-1, r+1) */
      const uint32_t hu0 = uhadd8(load4(pp - w), load4(pp - w + 1)); /* h(c, r-1) */
      const uint32_t hu4 = uhadd8(load4(pp - w - 1), load4(pp - w)); /* h(c-1, r-1) */
      sub[0] = usada8(a, h0, sub[0]);                                /* h(c, r) */
      sub[1] = usada8(a, uhadd8(h0, hn0), sub[1]);                   /* d(c, r) */
      sub[2] = usada8(a, uhadd8(load4(pp), load4(pp + w)), sub[2]);  /* g(c, r) */
      sub[3] = usada8(a, uhadd8(h4, hn4), sub[3]);                   /* d(c-1, r) */
      sub[4] = usada8(a, h4, sub[4]);                                /* h(c-1, r) */
      sub[5] = usada8(a, uhadd8(hu4, h4), sub[5]);                   /* d(c-1, r-1) */
      sub[6] = usada8(a, uhadd8(load4(pp - w), load4(pp)), sub[6]);  /* g(c, r-1) */
      sub[7] = usada8(a, uhadd8(hu0, h0), sub[7]);                   /* d(c, r-1) */
    }
  }
}

static const int8_t kStepX[PXFLOW_DIRECTIONS + 1] = PXFLOW_STEP_X_TABLE;
static const int8_t kStepY[PXFLOW_DIRECTIONS + 1] = PXFLOW_STEP_Y_TABLE;

static void clear_record(pxdut_record *rec) {
  uint8_t *bytes = (uint8_t *)rec;
  for (uint32_t i = 0; i < sizeof *rec; ++i) bytes[i] = 0;
}

static void flow_poi(const pxdut_params *p, const uint8_t *prev, const uint8_t *next, uint32_t x,
                     uint32_t y, pxdut_record *rec) {
  const uint32_t w = p->width;
  const int32_t s = (int32_t)p->search_radius;
  const uint8_t *blk = prev + y * w + x;
  clear_record(rec);
  rec->x = (uint16_t)x;
  rec->y = (uint16_t)y;
  rec->dir = PXFLOW_DIR_NONE;
  rec->feature = (uint16_t)feature(blk, w);
  if (rec->feature < p->feature_threshold) return; /* PXFLOW_STATUS_DROPPED (0, cleared) */

  block_words b;
  load_block(blk, w, &b);
  uint32_t best = PXFLOW_SAD_SENTINEL;
  int32_t bx = 0, by = 0;
  for (int32_t dy = -s; dy <= s; ++dy)
    for (int32_t dx = -s; dx <= s; ++dx) {
      const uint8_t *cand = next + (uint32_t)((int32_t)y + dy) * w + (uint32_t)((int32_t)x + dx);
      const uint32_t sad = block_sad(&b, cand, w);
      if (sad < best) { /* strict: a tie keeps the first candidate in raster order */
        best = sad;
        bx = dx;
        by = dy;
      }
    }
  rec->dx = (int8_t)bx;
  rec->dy = (int8_t)by;
  rec->sad = (uint16_t)best;
  if (best >= p->sad_threshold) {
    rec->status = PXFLOW_STATUS_REJECTED;
    return;
  }
  rec->status = PXFLOW_STATUS_ACCEPTED;
  uint32_t sub[8];
  const uint8_t *match = next + (uint32_t)((int32_t)y + by) * w + (uint32_t)((int32_t)x + bx);
  half_sads(&b, match, w, sub);
  int dir = PXFLOW_DIR_NONE; /* from (best, dir 8), k = 0..7 in order, strictly smaller replaces */
  for (int k = 0; k < 8; ++k) {
    rec->sub[k] = (uint16_t)sub[k];
    if (sub[k] < best) {
      best = sub[k];
      dir = k;
    }
  }
  rec->dir = (uint8_t)dir;
  rec->hx = (int8_t)(2 * bx + kStepX[dir]);
  rec->hy = (int8_t)(2 * by + kStepY[dir]);
}

void pxdut_kernel_portable(const pxdut_params *p, const uint8_t *prev, const uint8_t *next,
                           pxdut_record *out) {
  const pxflow_grid_axis ax = pxflow_grid_axis_of(p->width, p->search_radius, p->blocks);
  const pxflow_grid_axis ay = pxflow_grid_axis_of(p->height, p->search_radius, p->blocks);
  for (uint32_t j = 0; j < ay.count; ++j)
    for (uint32_t i = 0; i < ax.count; ++i)
      flow_poi(p, prev, next, ax.first + i * ax.step, ay.first + j * ay.step,
               &out[j * ax.count + i]);
}
