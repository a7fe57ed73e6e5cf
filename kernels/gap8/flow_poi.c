/* The per-POI kernel of SPEC §3 on one cluster core, shaped like the PX4FLOW firmware's
 * compute_flow: feature test, full integer search, half-pixel refinement. Every 4-byte SAD is
 * sad4_acc (four Xpulp instructions). */
#include <pmsis.h>

#include "flow_kernel.h"
#include "flow_simd.h"

/* Half-pixel step (sx, sy) of direction k; k = 8 is the integer match. */
static const int8_t kStepX[PXFLOW_DIRECTIONS + 1] = PXFLOW_STEP_X_TABLE;
static const int8_t kStepY[PXFLOW_DIRECTIONS + 1] = PXFLOW_STEP_Y_TABLE;

/* Four bytes of a column, packed like the firmware's col1..col4 (lanes are independent). */
static uint32_t column4(const uint8_t *p, uint32_t w) {
  return (uint32_t)p[0] | (uint32_t)p[w] << 8 | (uint32_t)p[2 * w] << 16 | (uint32_t)p[3 * w] << 24;
}

/* The firmware's compute_diff: 3 row and 3 column 4-byte differences of the central 4x4. */
static uint32_t feature(const uint8_t *blk, uint32_t w) {
  const uint8_t *q = blk + 2 * w + 2;
  uint32_t acc = sad4_acc(0, ld4(q), ld4(q + w));
  acc = sad4_acc(acc, ld4(q + w), ld4(q + 2 * w));
  acc = sad4_acc(acc, ld4(q + 2 * w), ld4(q + 3 * w));
  const uint32_t c0 = column4(q, w), c1 = column4(q + 1, w);
  const uint32_t c2 = column4(q + 2, w), c3 = column4(q + 3, w);
  acc = sad4_acc(acc, c0, c1);
  acc = sad4_acc(acc, c1, c2);
  return sad4_acc(acc, c2, c3);
}

/* The half-pixel vote from (best, dir 8): k = 0..7 in order, strictly smaller replaces. */
static void select_direction(pxflow_poi_record *rec, uint32_t best, const uint32_t sub[8]) {
  int dir = PXFLOW_DIR_NONE;
  for (int k = 0; k < 8; ++k) {
    rec->sub[k] = (uint16_t)sub[k];
    if (sub[k] < best) {
      best = sub[k];
      dir = k;
    }
  }
  rec->dir = (uint8_t)dir;
  rec->hx = (int8_t)(2 * rec->dx + kStepX[dir]);
  rec->hy = (int8_t)(2 * rec->dy + kStepY[dir]);
}

/* Fills the record of POI n; the master cleared it, so undefined fields stay 0. */
static void flow_poi(const flow_ctx *c, uint32_t n) {
  pxflow_poi_record *rec = &c->records[n];
  const uint32_t x = c->poi_xy[2 * n], y = c->poi_xy[2 * n + 1];
  const uint32_t w = c->width;
  const uint8_t *blk = c->prev + y * w + x;
  rec->x = (uint16_t)x;
  rec->y = (uint16_t)y;
  rec->dir = PXFLOW_DIR_NONE;
  rec->feature = (uint16_t)feature(blk, w);
  if (rec->feature < c->feature_threshold) return; /* PXFLOW_STATUS_DROPPED */
  int bx = 0, by = 0;
  const uint32_t best = flow_integer_search(c, blk, x, y, &bx, &by);
  rec->dx = (int8_t)bx;
  rec->dy = (int8_t)by;
  rec->sad = (uint16_t)best;
  if (best >= c->sad_threshold) {
    rec->status = PXFLOW_STATUS_REJECTED;
    return;
  }
  rec->status = PXFLOW_STATUS_ACCEPTED;
  uint32_t sub[8];
  variant_half_sads(c, blk, x + bx, y + by, sub);
  select_direction(rec, best, sub);
#ifdef PXFLOW_GAP8_FAST_HOOKS
  variant_accepted(c, rec);
#endif
}

void flow_team_entry(void *arg) {
  const flow_ctx *c = arg;
  const uint32_t core = (uint32_t)pi_core_id();
  variant_prepare(c, core);
  if (c->split == PXFLOW_GAP8_SPLIT_CHUNKED) {
    const uint32_t chunk = (c->pois + c->cores - 1) / c->cores;
    const uint32_t end = (core + 1) * chunk < c->pois ? (core + 1) * chunk : c->pois;
    for (uint32_t n = core * chunk; n < end; ++n) flow_poi(c, n);
  } else {
    for (uint32_t n = core; n < c->pois; n += c->cores) flow_poi(c, n);
  }
#ifdef PXFLOW_GAP8_FAST_HOOKS
  variant_finish(c, core);
#endif
}
