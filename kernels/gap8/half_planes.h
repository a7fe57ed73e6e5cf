/* The eight half-pixel SADs read from precomputed planes h, g, d (local and global variants).
 * h, g, d point at the plane cell of the matched block's top-left pixel; `stride` is the planes'
 * row pitch. Direction k's value at block pixel (c, r) is SPEC §3's table: h(c, r), d(c, r),
 * g(c, r), d(c-1, r), h(c-1, r), d(c-1, r-1), g(c, r-1), d(c, r-1).
 * One asm block: a hardware loop over the 8 block rows, both 4-pixel halves of a row in its body,
 * the eight accumulators in registers, every pointer advanced by its own post-increment load. */
#ifndef PXFLOW_GAP8_HALF_PLANES_H
#define PXFLOW_GAP8_HALF_PLANES_H

#include "flow_simd.h"

/* acc += USAD8(a, v), as sad4_acc (flow_simd.h), in registers t and u. */
#define HALF_SAD(acc, v)                                  \
  GAP8_ASM_PV_MAXU_B("%[t]", "%[a]", v)                   \
  GAP8_ASM_PV_MINU_B("%[u]", "%[a]", v)                   \
  GAP8_ASM_PV_SUB_B("%[t]", "%[t]", "%[u]")               \
  GAP8_ASM_PV_SDOTUP_SC_B(acc, "%[t]", "%[one]")

/* One 4-pixel half of a block row: prev's word `a`, 8 plane loads, 8 SADs. Each loaded value is
 * used two instructions later at the earliest (no load-use stall). `blk_load` loads `a`; `post`
 * is the form of each plane pointer's last load: +4 after the first half, to the next row after
 * the second. */
#define HALF_GROUP(blk_load, post)                                \
  blk_load                                                        \
  "lw %[v0], -1(%[ph])\n\t" /* h(c-1, r) */                        \
  post("%[v1]", "%[ph]")    /* h(c, r) */                          \
  HALF_SAD("%[acc4]", "%[v0]")                                    \
  "lw %[v0], -1(%[pd])\n\t" /* d(c-1, r) */                        \
  HALF_SAD("%[acc0]", "%[v1]")                                    \
  post("%[v1]", "%[pd]") /* d(c, r) */                             \
  HALF_SAD("%[acc3]", "%[v0]")                                    \
  post("%[v0]", "%[pg]") /* g(c, r) */                             \
  HALF_SAD("%[acc1]", "%[v1]")                                    \
  "lw %[v1], -1(%[pda])\n\t" /* d(c-1, r-1) */                     \
  HALF_SAD("%[acc2]", "%[v0]")                                    \
  post("%[v0]", "%[pda]") /* d(c, r-1) */                          \
  HALF_SAD("%[acc5]", "%[v1]")                                    \
  post("%[v1]", "%[pga]") /* g(c, r-1) */                          \
  HALF_SAD("%[acc7]", "%[v0]")                                    \
  HALF_SAD("%[acc6]", "%[v1]")

#define HALF_POST_4(rd, p) GAP8_ASM_P_LW_POST_IMM(rd, "4", p)
#define HALF_POST_ROW(rd, p) GAP8_ASM_P_LW_POST_REG(rd, "%[plane_rest]", p)

static inline void sads_from_planes(const uint8_t *blk, uint32_t w, const uint8_t *h,
                                    const uint8_t *g, const uint8_t *d, int stride,
                                    uint32_t sub[8]) {
  uint32_t acc0, acc1, acc2, acc3, acc4, acc5, acc6, acc7; /* set to 0 in the asm */
  uint32_t a, v0, v1, t, u;
  const uint8_t *pda = d - stride, *pga = g - stride; /* the row above: d(., r-1), g(., r-1) */
  const uint32_t blk_rest = w - 4, plane_rest = (uint32_t)stride - 4, one = 1;
  __asm__ volatile(
      ".option push\n\t.option norvc\n\t.option norelax\n\t"
      "li %[acc0], 0\n\tli %[acc1], 0\n\tli %[acc2], 0\n\tli %[acc3], 0\n\t"
      "li %[acc4], 0\n\tli %[acc5], 0\n\tli %[acc6], 0\n\tli %[acc7], 0\n\t"
      /* loop 0: 8 rows. The body (2 x 41 instructions) starts 12 bytes after lp.starti; its
       * last instruction is 336 bytes after lp.starti, 332 after lp.endi (166 half-words). */
      ".Lstart%=: " GAP8_ASM_LP_STARTI("0", "6")
      GAP8_ASM_LP_ENDI("0", "166")
      GAP8_ASM_LP_COUNTI("0", "8")
      ".Lbody%=: "
      HALF_GROUP(GAP8_ASM_P_LW_POST_IMM("%[a]", "4", "%[pb]"), HALF_POST_4)
      HALF_GROUP(GAP8_ASM_P_LW_POST_REG("%[a]", "%[blk_rest]", "%[pb]"), HALF_POST_ROW)
      ".Lafter%=:\n\t"
      GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lbody%=", "12")
      GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lafter%=", "340")
      ".option pop"
      : [acc0] "=&r"(acc0), [acc1] "=&r"(acc1), [acc2] "=&r"(acc2), [acc3] "=&r"(acc3),
        [acc4] "=&r"(acc4), [acc5] "=&r"(acc5), [acc6] "=&r"(acc6), [acc7] "=&r"(acc7),
        [pb] "+r"(blk), [ph] "+r"(h), [pd] "+r"(d), [pg] "+r"(g), [pda] "+r"(pda),
        [pga] "+r"(pga), [a] "=&r"(a), [v0] "=&r"(v0), [v1] "=&r"(v1), [t] "=&r"(t),
        [u] "=&r"(u)
      : [blk_rest] "r"(blk_rest), [plane_rest] "r"(plane_rest), [one] "r"(one)
      : "memory");
  sub[0] = acc0;
  sub[1] = acc1;
  sub[2] = acc2;
  sub[3] = acc3;
  sub[4] = acc4;
  sub[5] = acc5;
  sub[6] = acc6;
  sub[7] = acc7;
}

#undef HALF_POST_ROW
#undef HALF_POST_4
#undef HALF_GROUP
#undef HALF_SAD

#endif
