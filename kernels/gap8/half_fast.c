/* The fast variant's half-pixel step (beyond the paper): the local optimisation kept in
 * registers. Per 4-pixel group (c = 0, then c = 4) the block rows are walked top to bottom; at
 * row r the new values are those of row r+1, h(c, r+1) and h(c-1, r+1) from next's words
 * P(c-1..c+1, r+1), and from them d(c, r), d(c-1, r) and g(c, r): 5 floor averages per group
 * and row (SPEC §3's 300 interpolations per POI, plus the prologue's 4 of row -1). The values of
 * row r-1 the upward directions need (g, d) and h of row r stay in registers from the row
 * before. Per row and group: next's 3 words, prev's word, 5 averages (FLOOR_AVG_ASM), 8 SADs.
 * With the fast tables (fast_tables.h) the 3 words come aligned from the shifted copies of next,
 * else from next itself (misaligned loads, any width). */
#include "fast_tables.h"
#include "flow_simd.h"

/* The asm's scratch registers are fixed (an asm takes at most 30 operands): prev's word a in t0,
 * the SAD and average scratch in t1, t2, the rotating row values in t3..t6 and a0, a1, the
 * carried g, d, d of the row above in a2..a4. */
/* acc += USAD8(a, v) */
#define FAST_SAD(acc, v) SAD4_ACC_ASM(acc, "t0", v, "t1", "t2", "%[one]")
#define FAST_AVG(d, a, b) FLOOR_AVG_ASM(d, a, b, "t1")

/* One block row. On entry h(c, r) is in `ha`, h(c-1, r) in `hb`, P(c, r) in `pz`; gg, da,
 * db (a2..a4) hold g(c, r-1), d(c, r-1), d(c-1, r-1). Row r+1's words P(c-1), P(c), P(c+1) are
 * loaded into m, z, o; on exit h(c, r+1) is in o, h(c-1, r+1) in m, P(c, r+1) in z, and gg, da, db
 * hold row r's values. Every load is used four instructions later at the earliest. */
/* clang-format off */
#define FAST_ROW(ha, hb, pz, m, z, o)                                \
  GAP8_ASM_P_LW_POST_REG("t0", "%[w]", "%[pb]") /* prev, row r */  \
  GAP8_ASM_P_LW_POST_REG(m, "%[w]", "%[pm]")                         \
  GAP8_ASM_P_LW_POST_REG(z, "%[w]", "%[p0]")                         \
  GAP8_ASM_P_LW_POST_REG(o, "%[w]", "%[p1]")                         \
  FAST_SAD("%[acc0]", ha)             /* k0: h(c, r) */              \
  FAST_SAD("%[acc4]", hb)             /* k4: h(c-1, r) */            \
  FAST_SAD("%[acc6]", "a2")        /* k6: g(c, r-1) */            \
  FAST_SAD("%[acc7]", "a3")        /* k7: d(c, r-1) */            \
  FAST_SAD("%[acc5]", "a4")        /* k5: d(c-1, r-1) */          \
  FAST_AVG(o, z, o)                   /* h(c, r+1) */                \
  FAST_AVG(m, m, z)                   /* h(c-1, r+1) */              \
  FAST_AVG("a3", ha, o)            /* d(c, r) */                  \
  FAST_AVG("a4", hb, m)            /* d(c-1, r) */                \
  FAST_AVG("a2", pz, z)            /* g(c, r) */                  \
  FAST_SAD("%[acc1]", "a3")        /* k1: d(c, r) */              \
  FAST_SAD("%[acc3]", "a4")        /* k3: d(c-1, r) */            \
  FAST_SAD("%[acc2]", "a2")        /* k2: g(c, r) */

/* One 4-pixel group: the prologue (rows -1 and 0: 6 loads, 7 averages) leaves h(c, 0) in h0,
 * h(c-1, 0) in g0, P(c, 0) in z0 and row -1's g, d, d; then hardware loop 0, 4 iterations of two
 * rows (the second with the registers' roles swapped back). lp.starti/endi/counti: the body
 * starts 12 bytes after lp.starti, its last instruction is 2 x 56 - 1 instructions later, so
 * 12 + 111 * 4 = 456 bytes after lp.starti, 452 bytes (226 half-words) after lp.endi. */
#define FAST_GROUP                                                                \
  GAP8_ASM_P_LW_POST_REG("a0", "%[w]", "%[p1]")   /* P(c+1, -1) */              \
  GAP8_ASM_P_LW_POST_REG("a1", "%[w]", "%[p0]")  /* P(c, -1) */                \
  GAP8_ASM_P_LW_POST_REG("t6", "%[w]", "%[pm]")   /* P(c-1, -1) */              \
  GAP8_ASM_P_LW_POST_REG("t3", "%[w]", "%[p1]")  /* P(c+1, 0) */               \
  GAP8_ASM_P_LW_POST_REG("t5", "%[w]", "%[p0]")  /* P(c, 0) */                 \
  GAP8_ASM_P_LW_POST_REG("t4", "%[w]", "%[pm]")  /* P(c-1, 0) */               \
  FAST_AVG("a0", "a1", "a0")                 /* h(c, -1) */                \
  FAST_AVG("t6", "t6", "a1")                 /* h(c-1, -1) */              \
  FAST_AVG("a2", "a1", "t5")               /* g(c, -1) */                \
  FAST_AVG("t3", "t5", "t3")               /* h(c, 0) */                 \
  FAST_AVG("t4", "t4", "t5")               /* h(c-1, 0) */               \
  FAST_AVG("a3", "a0", "t3")                /* d(c, -1) */                \
  FAST_AVG("a4", "t6", "t4")                /* d(c-1, -1) */              \
  ".Lstart%=: " GAP8_ASM_LP_STARTI("0", "6") GAP8_ASM_LP_ENDI("0", "226")         \
  GAP8_ASM_LP_COUNTI("0", "4")                                                    \
  ".Lbody%=: "                                                                    \
  FAST_ROW("t3", "t4", "t5", "t6", "a1", "a0")                    \
  FAST_ROW("a0", "t6", "a1", "t4", "t5", "t3")                    \
  ".Lafter%=:\n\t"                                                                \
  GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lbody%=", "12")                          \
  GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lafter%=", "460")
/* clang-format on */

/* Row -1's words P(c-1), P(c), P(c+1) of group c: pointers into next, or into the aligned copy
 * of next that holds each word (W a multiple of 4: the same copy on every row). */
static void group_pointers(const flow_ctx *c, uint32_t o, const uint8_t *ptr[3]) {
  for (uint32_t e = 0; e < 3; ++e) {
    const uint32_t q = (o + e) & 3;
    ptr[e] = g_fast.ready ? g_fast.copy[q] + (o + e - q) : c->next + o + e;
  }
}

void variant_half_sads(const flow_ctx *c, const uint8_t *blk, uint32_t mx, uint32_t my,
                       uint32_t sub[8]) {
  const uint32_t w = c->width, one = 1;
  uint32_t acc0 = 0, acc1 = 0, acc2 = 0, acc3 = 0, acc4 = 0, acc5 = 0, acc6 = 0, acc7 = 0;
  for (uint32_t g = 0; g < 8; g += 4) {
    const uint8_t *ptr[3];
    group_pointers(c, (my - 1) * w + mx + g - 1, ptr);
    const uint8_t *pb = blk + g, *pm = ptr[0], *p0 = ptr[1], *p1 = ptr[2];
    __asm__ volatile(GAP8_ASM_HWLOOP_BEGIN FAST_GROUP GAP8_ASM_HWLOOP_END
                     : [acc0] "+r"(acc0), [acc1] "+r"(acc1), [acc2] "+r"(acc2), [acc3] "+r"(acc3),
                       [acc4] "+r"(acc4), [acc5] "+r"(acc5), [acc6] "+r"(acc6), [acc7] "+r"(acc7),
                       [pb] "+r"(pb), [pm] "+r"(pm), [p0] "+r"(p0), [p1] "+r"(p1)
                     : [w] "r"(w), [one] "r"(one)
                     : "t0", "t1", "t2", "t3", "t4", "t5", "t6", "a0", "a1", "a2", "a3", "a4",
                       "memory");
  }
  sub[0] = acc0, sub[1] = acc1, sub[2] = acc2, sub[3] = acc3;
  sub[4] = acc4, sub[5] = acc5, sub[6] = acc6, sub[7] = acc7;
}
