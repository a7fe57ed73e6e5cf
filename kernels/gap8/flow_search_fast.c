/* The integer search of the "fast" variant (beyond the paper). Two paths, the same records:
 *
 * The algebra path (W = 64 and the tables of fast_tables.h in L1): |a - b| = 2 max(a, b) - a - b,
 * so SAD = 2 M - A - B with M = sum of max(a, b) (pv.maxu.b, then pv.sdotup.sc.b with the scalar
 * 2: two instructions per 4 pixels), A the sum of prev's block (once per POI) and B the
 * candidate's block sum (the table, -B loaded as the accumulator's start). Each candidate reads
 * its 16 words aligned from the shifted copy of next that matches its alignment, so the
 * candidates are taken in four groups by dx mod 4 (one asm block per group: hardware loop 1
 * over the 2S+1 rows of displacements, loop 0 over the group's candidates in a row). No branch in
 * any loop: the best is kept by p.minu on the key (SAD + A) << 16 | (the candidate's table
 * address, low 16 bits): the smallest SAD, then the smallest table address, i.e. the first
 * candidate in raster order (the address grows with (y + dy) * W + x + dx), whatever the order
 * in which the groups are searched. SAD + A < 2^15 and the table lies in L1 (64 KiB), so the key
 * never wraps.
 *
 * The held-register path (any other frame): prev's block in 16 registers for all candidates,
 * 4 instructions per 4-pixel SAD, raster order by rows (search_raster.h). */
#include "fast_tables.h"
#include "search_raster.h"

/* clang-format off */
/* acc += 64 * USAD8(prev, v) (the key's scale, search_raster.h); v is overwritten. */
#define HELD_SAD(prev, v) SAD4_ACC_ASM("%[acc]", prev, v, "%[t]", v, "%[scale]")

/* Block row r: next's two words (the second load steps to the next row), two SADs against
 * prev's words lo and hi. The loads' values are used two instructions later at the earliest. */
#define HELD_ROW(lo, hi)                                                                       \
  GAP8_ASM_P_LW_POST_IMM("%[v0]", "4", "%[pb]")                                                \
  GAP8_ASM_P_LW_POST_REG("%[v1]", "%[rest]", "%[pb]")                                          \
  HELD_SAD("%[p" #lo "]", "%[v0]")                                                             \
  HELD_SAD("%[p" #hi "]", "%[v1]")
/* clang-format on */

/* Candidates row, row+1, ..., row+n-1 of next (row stride w) against prev's block held in
 * p[0..15]: returns the smallest key 64 * SAD + index (search_raster.h). */
static uint32_t search_row_held(const uint32_t p[16], const uint8_t *row, uint32_t w, uint32_t n) {
  const uint8_t *pb = row;
  uint32_t key = 0xFFFFFFFFu, acc, v0, v1, t;
  const uint32_t rest = w - 4, back = 8 * w - 1, scale = kKeyScale; /* back: to the next one */
  /* clang-format off */
  __asm__ volatile(
      GAP8_ASM_HWLOOP_BEGIN
      /* loop 1 over the n candidates, no branch in it (search_raster.h): 83 instructions after
       * lp.setup (the index, the 80 of the rows, p.minu, the step back), the last 332 bytes
       * (166 half-words) after lp.setup */
      ".Lcand%=: " GAP8_ASM_LP_SETUP("1", "%[n]", "166")
      "sub %[acc], %[pb], %[row]\n\t" /* the candidate's index dx + S: the key's low bits */
      HELD_ROW(0, 1) HELD_ROW(2, 3) HELD_ROW(4, 5) HELD_ROW(6, 7) HELD_ROW(8, 9)
      HELD_ROW(10, 11) HELD_ROW(12, 13) HELD_ROW(14, 15)
      P_MINU_ASM("%[key]", "%[key]", "%[acc]")
      "sub %[pb], %[pb], %[back]\n\t"
      ".Lcand_end%=:\n\t"
      GAP8_ASM_CHECK_DISTANCE(".Lcand%=", ".Lcand_end%=", "336") /* last at 332 */
      GAP8_ASM_HWLOOP_END
      : [key] "+&r"(key), [pb] "+&r"(pb), [acc] "=&r"(acc), [v0] "=&r"(v0), [v1] "=&r"(v1),
        [t] "=&r"(t)
      : [p0] "r"(p[0]), [p1] "r"(p[1]), [p2] "r"(p[2]), [p3] "r"(p[3]), [p4] "r"(p[4]),
        [p5] "r"(p[5]), [p6] "r"(p[6]), [p7] "r"(p[7]), [p8] "r"(p[8]), [p9] "r"(p[9]),
        [p10] "r"(p[10]), [p11] "r"(p[11]), [p12] "r"(p[12]), [p13] "r"(p[13]),
        [p14] "r"(p[14]), [p15] "r"(p[15]), [n] "r"(n), [row] "r"(row), [rest] "r"(rest),
        [back] "r"(back), [scale] "r"(scale)
      : "memory");
  /* clang-format on */
  return key;
}

/* clang-format off */
/* Block row r of the algebra path: next's two words at immediate offsets (W = 64) from pb, which
 * row 0's first load has already advanced by 4 (to the group's next candidate), acc += 2 *
 * sum(max) against prev's words lo and hi. */
#define MAX_SIMD(lo, hi)                                                                       \
  GAP8_ASM_PV_MAXU_B("%[v0]", "%[v0]", "%[p" #lo "]")                                          \
  GAP8_ASM_PV_SDOTUP_SC_B("%[acc]", "%[v0]", "%[two]")                                         \
  GAP8_ASM_PV_MAXU_B("%[v1]", "%[v1]", "%[p" #hi "]")                                          \
  GAP8_ASM_PV_SDOTUP_SC_B("%[acc]", "%[v1]", "%[two]")
#define MAX_ROW0                                                                               \
  GAP8_ASM_P_LW_POST_IMM("%[v0]", "4", "%[pb]")                                                \
  "lw %[v1], 0(%[pb])\n\t" MAX_SIMD(0, 1)
#define MAX_ROW(r, lo, hi)                                                                     \
  "lw %[v0], 64*" #r "-4(%[pb])\n\t"                                                           \
  "lw %[v1], 64*" #r "(%[pb])\n\t" MAX_SIMD(lo, hi)
/* clang-format on */

/* One group of candidates: `rows` rows of displacements, n candidates per row 4 pixels apart;
 * pb = the first candidate in its aligned copy, pt = its entry of neg_box. Returns the smaller
 * of `key` and the group's keys. */
static uint32_t search_group(const uint32_t p[16], const uint8_t *pb, const uint32_t *pt,
                             uint32_t n, uint32_t rows, uint32_t key) {
  uint32_t acc = rows, v0, v1;
  const uint32_t two = 2, pb_row = kFastWidth - 4 * n, pt_row = 4 * kFastWidth - 16 * n;
  /* clang-format off */
  __asm__ volatile(
      GAP8_ASM_HWLOOP_BEGIN
      /* loop 1 over the rows: lp.setup 0, loop 0's 52 instructions, two pointer steps; the last
       * 220 bytes (110 half-words) after lp.setup. Loop 0 over the candidates: -B, the 8 rows
       * (48, the first load steps pb), the key (slli, add, p.minu); the last 208 bytes (104
       * half-words) after its lp.setup. */
      ".Lrows%=: " GAP8_ASM_LP_SETUP("1", "%[acc]", "110")
      ".Lcand%=: " GAP8_ASM_LP_SETUP("0", "%[n]", "104")
      GAP8_ASM_P_LW_POST_IMM("%[acc]", "16", "%[pt]")    /* -B; pt to the next candidate */
      MAX_ROW0 MAX_ROW(1, 2, 3) MAX_ROW(2, 4, 5) MAX_ROW(3, 6, 7)
      MAX_ROW(4, 8, 9) MAX_ROW(5, 10, 11) MAX_ROW(6, 12, 13) MAX_ROW(7, 14, 15)
      "slli %[acc], %[acc], 16\n\t"                      /* (SAD + A) << 16 */
      "add %[acc], %[acc], %[pt]\n\t"                    /* | table address (+16) */
      ".Lcand_end%=: " P_MINU_ASM("%[key]", "%[key]", "%[acc]")
      "add %[pb], %[pb], %[pb_row]\n\t"
      ".Lrows_end%=: add %[pt], %[pt], %[pt_row]\n\t"
      GAP8_ASM_CHECK_DISTANCE(".Lcand%=", ".Lcand_end%=", "208")
      GAP8_ASM_CHECK_DISTANCE(".Lrows%=", ".Lrows_end%=", "220")
      GAP8_ASM_HWLOOP_END
      : [key] "+&r"(key), [pb] "+&r"(pb), [pt] "+&r"(pt), [acc] "+&r"(acc), [v0] "=&r"(v0),
        [v1] "=&r"(v1)
      : [p0] "r"(p[0]), [p1] "r"(p[1]), [p2] "r"(p[2]), [p3] "r"(p[3]), [p4] "r"(p[4]),
        [p5] "r"(p[5]), [p6] "r"(p[6]), [p7] "r"(p[7]), [p8] "r"(p[8]), [p9] "r"(p[9]),
        [p10] "r"(p[10]), [p11] "r"(p[11]), [p12] "r"(p[12]), [p13] "r"(p[13]),
        [p14] "r"(p[14]), [p15] "r"(p[15]), [n] "r"(n), [two] "r"(two), [pb_row] "r"(pb_row),
        [pt_row] "r"(pt_row)
      : "memory");
  /* clang-format on */
  return key;
}

static uint32_t algebra_search(const flow_ctx *c, const uint8_t *blk, uint32_t x, uint32_t y,
                               int *bx, int *by) {
  const uint32_t s = c->search_radius, w = kFastWidth;
  uint32_t p[16], a = 0;
  for (int r = 0; r < 8; ++r) {
    p[2 * r] = ld4(blk + r * w);
    p[2 * r + 1] = ld4(blk + r * w + 4);
    a = gap8_pv_sdotup_sc_b(gap8_pv_sdotup_sc_b(a, p[2 * r], 1u), p[2 * r + 1], 1u);
  }
  const uint32_t o0 = (y - s) * w + x - s; /* the first candidate's pixel offset */
  uint32_t key = 0xFFFFFFFFu;
  for (uint32_t j = 0; j < 4 && j <= 2 * s; ++j) {
    const uint32_t o = o0 + j, q = o & 3;
    key = search_group(p, g_fast.copy[q] + (o - q), g_fast.neg_box + o, (2 * s - j) / 4 + 1,
                       2 * s + 1, key);
  }
  /* key = (SAD + A + 0x1000) << 16 | low half of (&neg_box[o] + 16), L1 at 0x10000000. */
  const uint32_t entry = 0x10000000u + (key & 0xFFFFu) - 16;
  const uint32_t o = (entry - (uint32_t)g_fast.neg_box) / 4;
  *bx = (int)(o % w) - (int)x;
  *by = (int)(o / w) - (int)y;
  return (key >> 16) - 0x1000u - a;
}

uint32_t flow_integer_search(const flow_ctx *c, const uint8_t *blk, uint32_t x, uint32_t y, int *bx,
                             int *by) {
  if (g_fast.ready) return algebra_search(c, blk, x, y, bx, by);
  return search_raster(c, blk, x, y, bx, by, search_row_held);
}
