/* The one per-POI kernel of SPEC §3-§4 in the PX4FLOW firmware's shape (compute_diff,
 * compute_sad_8x8, compute_subpixel of PX4/PX4-Flow src/modules/flow/flow.c), shared by dut/,
 * kernels/cortex-m4 and kernels/gap8. Every pixel operation is one of the firmware's 4-byte
 * primitives (SPEC §7), which the including target supplies through its own header as macros
 * before it includes this one:
 *
 *   PXFLOW_POI_LD4(p)             four pixels at any address as one word (lanes independent)
 *   PXFLOW_POI_SAD4_ACC(acc, a, b) acc + the sum over the four bytes of |a_i - b_i| (USADA8)
 *   PXFLOW_POI_AVG4(a, b)         floor((a_i + b_i) / 2) per byte, 9-bit intermediate (UHADD8)
 *
 * dut/src/pxdut_primitives.h writes them in plain C, kernels/cortex-m4/m4_simd.h as the DSP
 * instructions, kernels/gap8/flow_simd.h in Xpulp instructions. The target also names its context
 * type PXFLOW_POI_CONTEXT: a struct with the fields width, search_radius, feature_threshold and
 * sad_threshold (pxflow_param_block, or the GAP8 kernel's flow_ctx), read where the kernel uses
 * them. The integer search and the half-pixel SADs are steps a target may replace (GAP8 does, with
 * its asm hardware loops) by defining PXFLOW_POI_INTEGER_SEARCH and PXFLOW_POI_HALF_SADS with
 * the signatures of pxflow_poi_integer_search and pxflow_poi_half_sads below; otherwise those
 * portable steps run. PXFLOW_POI_ACCEPTED(ctx, rec), if defined, runs after each accepted POI's
 * record is complete (the GAP8 fast variant's histograms). Freestanding C99: each target
 * compiles it with its own compiler and flags, so that its primitives inline into the loops. The
 * functions are static, not static inline, as they were in each target's own copy: the compiler
 * then inlines by its own measure (inline, the M4's 16 calls of pxflow_poi_half_group per POI
 * grow the kernel and cost instructions), and a target compiles only the steps it uses. */
#ifndef PXFLOW_SPEC_POI_KERNEL_H
#define PXFLOW_SPEC_POI_KERNEL_H

#include <stddef.h>
#include <stdint.h>

#include "params.h"
#include "record.h"

#if !defined(PXFLOW_POI_LD4) || !defined(PXFLOW_POI_SAD4_ACC) || !defined(PXFLOW_POI_AVG4) || \
    !defined(PXFLOW_POI_CONTEXT)
#error "include the target's primitives header (PXFLOW_POI_LD4, _SAD4_ACC, _AVG4, _CONTEXT) first"
#endif

/* Four pixels of a column packed into a word, as the firmware's col1..col4 (its byte order is the
 * reverse; lanes are independent, so the SAD is the same). */
static uint32_t pxflow_poi_column4(const uint8_t *q, uint32_t w) {
  return (uint32_t)q[0] | (uint32_t)q[w] << 8 | (uint32_t)q[2 * w] << 16 | (uint32_t)q[3 * w] << 24;
}

/* compute_diff: the 24 neighbour differences of the block's central 4x4 (SPEC §3 step 1), as 3
 * row and 3 column 4-byte SADs. At most 24 x 255 = 6,120. */
static uint32_t pxflow_poi_feature(const uint8_t *blk, uint32_t w) {
  const uint8_t *q = blk + 2 * w + 2;
  uint32_t acc = PXFLOW_POI_SAD4_ACC(0, PXFLOW_POI_LD4(q), PXFLOW_POI_LD4(q + w));
  acc = PXFLOW_POI_SAD4_ACC(acc, PXFLOW_POI_LD4(q + w), PXFLOW_POI_LD4(q + 2 * w));
  acc = PXFLOW_POI_SAD4_ACC(acc, PXFLOW_POI_LD4(q + 2 * w), PXFLOW_POI_LD4(q + 3 * w));
  const uint32_t c0 = pxflow_poi_column4(q, w), c1 = pxflow_poi_column4(q + 1, w);
  const uint32_t c2 = pxflow_poi_column4(q + 2, w), c3 = pxflow_poi_column4(q + 3, w);
  acc = PXFLOW_POI_SAD4_ACC(acc, c0, c1);
  acc = PXFLOW_POI_SAD4_ACC(acc, c1, c2);
  return PXFLOW_POI_SAD4_ACC(acc, c2, c3);
}

#ifndef PXFLOW_POI_INTEGER_SEARCH
/* compute_sad_8x8: 16 4-byte SADs over two 8x8 blocks of stride w. At most 16,320. */
static uint32_t pxflow_poi_sad_8x8(const uint8_t *a, const uint8_t *b, uint32_t w) {
  uint32_t acc = 0;
  for (uint32_t r = 0; r < 8; ++r, a += w, b += w) {
    acc = PXFLOW_POI_SAD4_ACC(acc, PXFLOW_POI_LD4(a), PXFLOW_POI_LD4(b));
    acc = PXFLOW_POI_SAD4_ACC(acc, PXFLOW_POI_LD4(a + 4), PXFLOW_POI_LD4(b + 4));
  }
  return acc;
}

/* A function of its own, not inlined into the kernel (GCC and Clang): alone, the search's loop
 * state stays in the Cortex-M4's registers, where arm-none-eabi-gcc 12 spilled some of it inside
 * the kernel (docs/measurements/poi-kernel.md: 4% fewer instructions per frame). */
#if defined(__GNUC__)
#define PXFLOW_POI_NOINLINE __attribute__((noinline))
#else
#define PXFLOW_POI_NOINLINE
#endif

/* SPEC §3 step 2 for prev's block `blk` at (x, y): dy outer, dx inner, both -S..S; only a strictly
 * smaller SAD replaces, so a tie keeps the first candidate in raster order. Returns the best SAD
 * and its displacement. */
PXFLOW_POI_NOINLINE static uint32_t pxflow_poi_integer_search(const PXFLOW_POI_CONTEXT *ctx,
                                                              const uint8_t *next,
                                                              const uint8_t *blk, uint32_t x,
                                                              uint32_t y, int *bx, int *by) {
  const uint32_t w = ctx->width;
  const int s = (int)ctx->search_radius;
  uint32_t best = PXFLOW_SAD_SENTINEL;
  *bx = *by = 0;
  for (int dy = -s; dy <= s; ++dy) {
    const uint8_t *row = next + (size_t)((int)y + dy) * w + x;
    for (int dx = -s; dx <= s; ++dx) {
      const uint32_t d = pxflow_poi_sad_8x8(blk, row + dx, w);
      if (d < best) {
        best = d;
        *bx = dx;
        *by = dy;
      }
    }
  }
  return best;
}
#define PXFLOW_POI_INTEGER_SEARCH pxflow_poi_integer_search
#endif

#ifndef PXFLOW_POI_HALF_SADS
/* compute_subpixel for the 4 pixels at column offset c of row r: `a` is prev's word, `p` points
 * at P(c, r) of next (the matched block's pixel), w is the stride. The s values are the
 * firmware's: s0 = h(c, r), s1 = h(c, r+1), s2 = g(c, r), s3 = h(c-1, r+1), s4 = h(c-1, r),
 * s5 = h(c-1, r-1), s6 = g(c, r-1), s7 = h(c, r-1); the diagonals are floor averages of two
 * horizontal averages, each floored (SPEC §3: d(u, v) = avg(h(u, v), h(u, v+1))):
 * t1 = d(c, r), t3 = d(c-1, r), t5 = d(c-1, r-1), t7 = d(c, r-1). Directions 0..7 are then
 * s0, t1, s2, t3, s4, t5, s6, t7, exactly SPEC §3's table. 12 averages and 8 SADs. */
static void pxflow_poi_half_group(uint32_t a, const uint8_t *p, uint32_t w, uint32_t acc[8]) {
  const uint8_t *up = p - w, *down = p + w;
  const uint32_t centre = PXFLOW_POI_LD4(p), below = PXFLOW_POI_LD4(down);
  const uint32_t above = PXFLOW_POI_LD4(up);
  const uint32_t s0 = PXFLOW_POI_AVG4(centre, PXFLOW_POI_LD4(p + 1));
  const uint32_t s1 = PXFLOW_POI_AVG4(below, PXFLOW_POI_LD4(down + 1));
  const uint32_t s2 = PXFLOW_POI_AVG4(centre, below);
  const uint32_t s3 = PXFLOW_POI_AVG4(below, PXFLOW_POI_LD4(down - 1));
  const uint32_t s4 = PXFLOW_POI_AVG4(centre, PXFLOW_POI_LD4(p - 1));
  const uint32_t s5 = PXFLOW_POI_AVG4(above, PXFLOW_POI_LD4(up - 1));
  const uint32_t s6 = PXFLOW_POI_AVG4(centre, above);
  const uint32_t s7 = PXFLOW_POI_AVG4(above, PXFLOW_POI_LD4(up + 1));
  const uint32_t t1 = PXFLOW_POI_AVG4(s0, s1);
  const uint32_t t3 = PXFLOW_POI_AVG4(s3, s4);
  const uint32_t t5 = PXFLOW_POI_AVG4(s4, s5);
  const uint32_t t7 = PXFLOW_POI_AVG4(s7, s0);
  acc[0] = PXFLOW_POI_SAD4_ACC(acc[0], a, s0);
  acc[1] = PXFLOW_POI_SAD4_ACC(acc[1], a, t1);
  acc[2] = PXFLOW_POI_SAD4_ACC(acc[2], a, s2);
  acc[3] = PXFLOW_POI_SAD4_ACC(acc[3], a, t3);
  acc[4] = PXFLOW_POI_SAD4_ACC(acc[4], a, s4);
  acc[5] = PXFLOW_POI_SAD4_ACC(acc[5], a, t5);
  acc[6] = PXFLOW_POI_SAD4_ACC(acc[6], a, s6);
  acc[7] = PXFLOW_POI_SAD4_ACC(acc[7], a, t7);
}

/* The eight half-pixel SADs of prev's block `blk` against the neighbourhood of next's matched
 * block, whose top-left corner is (mx, my): 8 rows of two 4-pixel groups. Reads rows -1..8 and
 * columns -1..8 around it. */
static void pxflow_poi_half_sads(const PXFLOW_POI_CONTEXT *ctx, const uint8_t *next,
                                 const uint8_t *blk, uint32_t mx, uint32_t my, uint32_t acc[8]) {
  const uint32_t w = ctx->width;
  const uint8_t *m = next + (size_t)my * w + mx;
  for (int k = 0; k < 8; ++k) acc[k] = 0;
  for (uint32_t r = 0; r < 8; ++r, blk += w, m += w) {
    pxflow_poi_half_group(PXFLOW_POI_LD4(blk), m, w, acc);
    pxflow_poi_half_group(PXFLOW_POI_LD4(blk + 4), m + 4, w, acc);
  }
}
#define PXFLOW_POI_HALF_SADS pxflow_poi_half_sads
#endif

/* The half-pixel vote from (best, dir 8): k = 0..7 in order, strictly smaller replaces, so ties
 * keep the lower k and a half step wins only when strictly better than the integer match. */
static void pxflow_poi_select_direction(pxflow_poi_record *rec, uint32_t best,
                                        const uint32_t sub[8]) {
  static const int8_t step_x[PXFLOW_DIRECTIONS + 1] = PXFLOW_STEP_X_TABLE;
  static const int8_t step_y[PXFLOW_DIRECTIONS + 1] = PXFLOW_STEP_Y_TABLE;
  int dir = PXFLOW_DIR_NONE;
  for (int k = 0; k < 8; ++k) {
    rec->sub[k] = (uint16_t)sub[k];
    if (sub[k] < best) {
      best = sub[k];
      dir = k;
    }
  }
  rec->dir = (uint8_t)dir;
  rec->hx = (int8_t)(2 * rec->dx + step_x[dir]);
  rec->hy = (int8_t)(2 * rec->dy + step_y[dir]);
}

/* The record of the POI whose block's top-left corner is (x, y) of prev (SPEC §3-§4); prev and
 * next are W x H, stride W. `rec` must be all zero on entry: the fields a status does not define
 * and the padding stay 0. */
static void pxflow_poi_kernel(const PXFLOW_POI_CONTEXT *ctx, const uint8_t *prev,
                              const uint8_t *next, uint32_t x, uint32_t y, pxflow_poi_record *rec) {
  const uint32_t w = ctx->width;
  const uint8_t *blk = prev + (size_t)y * w + x;
  rec->x = (uint16_t)x;
  rec->y = (uint16_t)y;
  rec->dir = PXFLOW_DIR_NONE;
  rec->feature = (uint16_t)pxflow_poi_feature(blk, w);
  if (rec->feature < ctx->feature_threshold) return; /* PXFLOW_STATUS_DROPPED (0) */
  int bx = 0, by = 0;
  const uint32_t best = PXFLOW_POI_INTEGER_SEARCH(ctx, next, blk, x, y, &bx, &by);
  rec->dx = (int8_t)bx;
  rec->dy = (int8_t)by;
  rec->sad = (uint16_t)best;
  if (best >= ctx->sad_threshold) {
    rec->status = PXFLOW_STATUS_REJECTED;
    return;
  }
  rec->status = PXFLOW_STATUS_ACCEPTED;
  uint32_t sub[8];
  PXFLOW_POI_HALF_SADS(ctx, next, blk, x + (uint32_t)bx, y + (uint32_t)by, sub);
  pxflow_poi_select_direction(rec, best, sub);
#ifdef PXFLOW_POI_ACCEPTED
  PXFLOW_POI_ACCEPTED(ctx, rec);
#endif
}

#endif
