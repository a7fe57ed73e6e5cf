/* Variant "original": the firmware's compute_subpixel. For each 4-pixel group of each block
 * row, the eight directions' values are interpolated on the spot from next (8 horizontal and
 * vertical averages, 4 diagonals as averages of two horizontal ones), then eight SADs. Shared
 * values are recomputed by every direction and every POI: 768 interpolations per POI.
 * One asm block: a hardware loop over the 8 block rows, both 4-pixel groups of a row in its
 * body, post-increment loads, the eight accumulators in registers. */
#include "flow_kernel.h"
#include "flow_simd.h"

const uint32_t variant_planes = 0;

void variant_prepare(const flow_ctx *c, uint32_t core) {
  (void)c;
  (void)core;
}

/* acc += USAD8(a, v); v is overwritten (each value feeds one SAD only). */
#define ORIG_SAD(acc, v) SAD4_ACC_ASM(acc, "%[a]", v, "%[t]", v, "%[one]")

/* One 4-pixel group (pixels c..c+3 of block row r): prev's word `a`; P(c-1..c+4) of rows r, r+1
 * and r-1 of next (9 loads); s0..s7 of the firmware (12 floor averages of 4 instructions each,
 * FLOOR_AVG_ASM, with the diagonals); 8 SADs.
 * Every loaded value is used three instructions later at the earliest (no load-use stall).
 * `blk_load` loads `a`; `post` is the form of each row pointer's last load: +4 after the first
 * group, to the next row after the second. */
/* clang-format off */
#define ORIG_GROUP(blk_load, post)                                                \
  blk_load                                                                        \
  "lw %[x0], -1(%[pp])\n\t"                     /* P(c-1, r) */                   \
  "lw %[x1], 1(%[pp])\n\t"                      /* P(c+1, r) */                   \
  post("%[x2]", "%[pp]")                        /* P(c, r) */                     \
  "lw %[x3], -1(%[pn])\n\t"                     /* P(c-1, r+1) */                 \
  FLOOR_AVG_ASM("%[x0]", "%[x2]", "%[x0]", "%[t]") /* s4 = h(c-1, r) */              \
  FLOOR_AVG_ASM("%[x1]", "%[x2]", "%[x1]", "%[t]") /* s0 = h(c, r) */                \
  "lw %[x4], 1(%[pn])\n\t"                      /* P(c+1, r+1) */                 \
  post("%[x5]", "%[pn]")                        /* P(c, r+1) */                   \
  "lw %[x6], -1(%[pu])\n\t"                     /* P(c-1, r-1) */                 \
  "lw %[x7], 1(%[pu])\n\t"                      /* P(c+1, r-1) */                 \
  post("%[x8]", "%[pu]")                        /* P(c, r-1) */                   \
  FLOOR_AVG_ASM("%[x4]", "%[x5]", "%[x4]", "%[t]") /* s1 = h(c, r+1) */              \
  FLOOR_AVG_ASM("%[x3]", "%[x5]", "%[x3]", "%[t]") /* s3 = h(c-1, r+1) */            \
  FLOOR_AVG_ASM("%[x5]", "%[x2]", "%[x5]", "%[t]") /* s2 = g(c, r) */                \
  FLOOR_AVG_ASM("%[x6]", "%[x8]", "%[x6]", "%[t]") /* s5 = h(c-1, r-1) */            \
  FLOOR_AVG_ASM("%[x7]", "%[x8]", "%[x7]", "%[t]") /* s7 = h(c, r-1) */              \
  FLOOR_AVG_ASM("%[x8]", "%[x2]", "%[x8]", "%[t]") /* s6 = g(c, r-1) */              \
  FLOOR_AVG_ASM("%[x4]", "%[x1]", "%[x4]", "%[t]") /* d(c, r) = avg(s0, s1) */       \
  FLOOR_AVG_ASM("%[x3]", "%[x3]", "%[x0]", "%[t]") /* d(c-1, r) = avg(s3, s4) */     \
  FLOOR_AVG_ASM("%[x6]", "%[x0]", "%[x6]", "%[t]") /* d(c-1, r-1) = avg(s4, s5) */   \
  FLOOR_AVG_ASM("%[x7]", "%[x7]", "%[x1]", "%[t]") /* d(c, r-1) = avg(s7, s0) */     \
  ORIG_SAD("%[acc0]", "%[x1]")                                                    \
  ORIG_SAD("%[acc1]", "%[x4]")                                                    \
  ORIG_SAD("%[acc2]", "%[x5]")                                                    \
  ORIG_SAD("%[acc3]", "%[x3]")                                                    \
  ORIG_SAD("%[acc4]", "%[x0]")                                                    \
  ORIG_SAD("%[acc5]", "%[x6]")                                                    \
  ORIG_SAD("%[acc6]", "%[x8]")                                                    \
  ORIG_SAD("%[acc7]", "%[x7]")
/* clang-format on */

#define ORIG_POST_4(rd, p) GAP8_ASM_P_LW_POST_IMM(rd, "4", p)
#define ORIG_POST_ROW(rd, p) GAP8_ASM_P_LW_POST_REG(rd, "%[rest]", p)

void variant_half_sads(const flow_ctx *c, const uint8_t *blk, uint32_t mx, uint32_t my,
                       uint32_t sub[8]) {
  const uint32_t w = c->width;
  const uint8_t *pp = c->next + my * w + mx; /* P(0, r): the matched block's row r */
  const uint8_t *pu = pp - w, *pn = pp + w;  /* rows r-1 and r+1 */
  const uint32_t rest = w - 4, one = 1;
  uint32_t a, t, x0, x1, x2, x3, x4, x5, x6, x7, x8;
  /* clang-format off */
  __asm__ volatile(
      /* body: 2 x 90 instructions, the last 12 + 179 * 4 = 728 bytes after lp.starti, so 724
       * bytes (362 half-words) after lp.endi */
      HALF_ROWS_ASM(ORIG_GROUP(GAP8_ASM_P_LW_POST_IMM("%[a]", "4", "%[pb]"), ORIG_POST_4),
                    ORIG_GROUP(GAP8_ASM_P_LW_POST_REG("%[a]", "%[rest]", "%[pb]"), ORIG_POST_ROW),
                    "362")
      : HALF_ACC_OPERANDS(sub), [pb] "+r"(blk), [pp] "+r"(pp), [pu] "+r"(pu), [pn] "+r"(pn),
        [a] "=&r"(a), [t] "=&r"(t), [x0] "=&r"(x0), [x1] "=&r"(x1), [x2] "=&r"(x2), [x3] "=&r"(x3),
        [x4] "=&r"(x4), [x5] "=&r"(x5), [x6] "=&r"(x6), [x7] "=&r"(x7), [x8] "=&r"(x8)
      : [rest] "r"(rest), [one] "r"(one)
      : "memory");
  /* clang-format on */
}
