/* The eight half-pixel SADs read from precomputed planes h, g, d (local and global variants).
 * h, g, d point at the plane cell of the matched block's top-left pixel; `stride` is the planes'
 * row pitch. Direction k's value at block pixel (c, r) is SPEC §3's table: h(c, r), d(c, r),
 * g(c, r), d(c-1, r), h(c-1, r), d(c-1, r-1), g(c, r-1), d(c, r-1).
 * One asm block: a hardware loop over the 8 block rows, both 4-pixel halves of a row in its body,
 * the eight accumulators in registers, every pointer advanced by its own post-increment load. */
#ifndef PXFLOW_GAP8_HALF_PLANES_H
#define PXFLOW_GAP8_HALF_PLANES_H

#include "flow_simd.h"

/* acc += USAD8(a, v) */
#define HALF_SAD(acc, v) SAD4_ACC_ASM(acc, "%[a]", v, "%[t]", "%[u]", "%[one]")

/* One 4-pixel half of a block row: prev's word `a`, 8 plane loads, 8 SADs. Each loaded value is
 * used two instructions later at the earliest (no load-use stall). `blk_load` loads `a`; `post`
 * is the form of each plane pointer's last load: +4 after the first half, to the next row after
 * the second. */
/* clang-format off */
#define HALF_GROUP(blk_load, post)                          \
  blk_load                                                  \
  "lw %[v0], -1(%[ph])\n\t"  /* h(c-1, r) */                \
  post("%[v1]", "%[ph]")     /* h(c, r) */                  \
  HALF_SAD("%[acc4]", "%[v0]")                              \
  "lw %[v0], -1(%[pd])\n\t"  /* d(c-1, r) */                \
  HALF_SAD("%[acc0]", "%[v1]")                              \
  post("%[v1]", "%[pd]")     /* d(c, r) */                  \
  HALF_SAD("%[acc3]", "%[v0]")                              \
  post("%[v0]", "%[pg]")     /* g(c, r) */                  \
  HALF_SAD("%[acc1]", "%[v1]")                              \
  "lw %[v1], -1(%[pda])\n\t" /* d(c-1, r-1) */              \
  HALF_SAD("%[acc2]", "%[v0]")                              \
  post("%[v0]", "%[pda]")    /* d(c, r-1) */                \
  HALF_SAD("%[acc5]", "%[v1]")                              \
  post("%[v1]", "%[pga]")    /* g(c, r-1) */                \
  HALF_SAD("%[acc7]", "%[v0]")                              \
  HALF_SAD("%[acc6]", "%[v1]")
/* clang-format on */

#define HALF_POST_4(rd, p) GAP8_ASM_P_LW_POST_IMM(rd, "4", p)
#define HALF_POST_ROW(rd, p) GAP8_ASM_P_LW_POST_REG(rd, "%[plane_rest]", p)

static inline void sads_from_planes(const uint8_t *blk, uint32_t w, const uint8_t *h,
                                    const uint8_t *g, const uint8_t *d, int stride,
                                    uint32_t sub[8]) {
  uint32_t a, v0, v1, t, u;
  const uint8_t *pda = d - stride, *pga = g - stride; /* the row above: d(., r-1), g(., r-1) */
  const uint32_t blk_rest = w - 4, plane_rest = (uint32_t)stride - 4, one = 1;
  /* clang-format off */
  __asm__ volatile(
      /* body: 2 x 41 instructions, the last 12 + 81 * 4 = 336 bytes after lp.starti, so 332
       * bytes (166 half-words) after lp.endi */
      HALF_ROWS_ASM(HALF_GROUP(GAP8_ASM_P_LW_POST_IMM("%[a]", "4", "%[pb]"), HALF_POST_4),
                    HALF_GROUP(GAP8_ASM_P_LW_POST_REG("%[a]", "%[blk_rest]", "%[pb]"),
                               HALF_POST_ROW),
                    "166")
      : HALF_ACC_OPERANDS(sub), [pb] "+r"(blk), [ph] "+r"(h), [pd] "+r"(d), [pg] "+r"(g),
        [pda] "+r"(pda), [pga] "+r"(pga), [a] "=&r"(a), [v0] "=&r"(v0), [v1] "=&r"(v1),
        [t] "=&r"(t), [u] "=&r"(u)
      : [blk_rest] "r"(blk_rest), [plane_rest] "r"(plane_rest), [one] "r"(one)
      : "memory");
  /* clang-format on */
}

#undef HALF_POST_ROW
#undef HALF_POST_4
#undef HALF_GROUP
#undef HALF_SAD

#endif
