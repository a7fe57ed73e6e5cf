/* The half-pixel step with the local optimisation kept in registers (local and fast variants).
 * Per 4-pixel group (c = 0, then c = 4) the block rows are walked top to bottom; at row r the new
 * values are those of row r+1, h(c, r+1) and h(c-1, r+1) from next's words P(c-1..c+1, r+1), and
 * from them d(c, r), d(c-1, r) and g(c, r): 5 floor averages per group and row, the paper's
 * 300 interpolations per POI (SPEC §6; 8 more in the prologue's row -1 and the last row's
 * unused h). The values of row r-1 that the upward directions need (g, d) and h of row r stay in
 * registers from the row before; nothing goes to the stack. Per row and group: next's 3 words,
 * prev's word, 5 averages (FLOOR_AVG_ASM), 8 SADs (flow_simd.h). */
#ifndef PXFLOW_GAP8_HALF_REGISTERS_H
#define PXFLOW_GAP8_HALF_REGISTERS_H

#include "flow_simd.h"

/* The asm's scratch registers are fixed, named here (an asm takes at most 30 operands, and the
 * eight accumulators and four pointers are in-out): prev's word, the SAD and average scratch,
 * the six rotating row values, the carried g, d, d of the row above. */
#define R_A "t0"
#define R_T "t1"
#define R_U "t2"
#define R_H0 "t3"
#define R_G0 "t4"
#define R_Z0 "t5"
#define R_X "t6"
#define R_Y "a0"
#define R_Z1 "a1"
#define R_GG "a2"
#define R_DA "a3"
#define R_DB "a4"
#define HALF_REG_CLOBBERS "t0", "t1", "t2", "t3", "t4", "t5", "t6", "a0", "a1", "a2", "a3", "a4"
/* acc += USAD8(a, v) */
#define REG_SAD(acc, v) SAD4_ACC_ASM(acc, R_A, v, R_T, R_U, "%[one]")
#define REG_AVG(d, a, b) FLOOR_AVG_ASM(d, a, b, R_T)

/* One block row. On entry h(c, r) is in `ha`, h(c-1, r) in `hb`, P(c, r) in `pz`; gg, da,
 * db (a2..a4) hold g(c, r-1), d(c, r-1), d(c-1, r-1). Row r+1's words P(c-1), P(c), P(c+1) are
 * loaded into m, z, o; on exit h(c, r+1) is in o, h(c-1, r+1) in m, P(c, r+1) in z, and gg, da, db
 * hold row r's values. Every load is used four instructions later at the earliest. */
/* clang-format off */
#define REG_ROW(ha, hb, pz, m, z, o)                                                           \
  GAP8_ASM_P_LW_POST_REG(R_A, "%[w]", "%[pb]") /* prev, row r */                               \
  GAP8_ASM_P_LW_POST_REG(m, "%[w]", "%[pm]")                                                   \
  GAP8_ASM_P_LW_POST_REG(z, "%[w]", "%[p0]")                                                   \
  GAP8_ASM_P_LW_POST_REG(o, "%[w]", "%[p1]")                                                   \
  REG_SAD("%[acc0]", ha)             /* k0: h(c, r) */                                         \
  REG_SAD("%[acc4]", hb)             /* k4: h(c-1, r) */                                       \
  REG_SAD("%[acc6]", R_GG)        /* k6: g(c, r-1) */                                          \
  REG_SAD("%[acc7]", R_DA)        /* k7: d(c, r-1) */                                          \
  REG_SAD("%[acc5]", R_DB)        /* k5: d(c-1, r-1) */                                        \
  REG_AVG(o, z, o)                   /* h(c, r+1) */                                           \
  REG_AVG(m, m, z)                   /* h(c-1, r+1) */                                         \
  REG_AVG(R_DA, ha, o)            /* d(c, r) */                                                \
  REG_AVG(R_DB, hb, m)            /* d(c-1, r) */                                              \
  REG_AVG(R_GG, pz, z)            /* g(c, r) */                                                \
  REG_SAD("%[acc1]", R_DA)        /* k1: d(c, r) */                                            \
  REG_SAD("%[acc3]", R_DB)        /* k3: d(c-1, r) */                                          \
  REG_SAD("%[acc2]", R_GG)        /* k2: g(c, r) */

/* One 4-pixel group: the prologue (rows -1 and 0: 6 loads, 7 averages) leaves h(c, 0) in h0,
 * h(c-1, 0) in g0, P(c, 0) in z0 and row -1's g, d, d; then hardware loop 0, 4 iterations of two
 * rows (the second with the registers' roles swapped back). lp.starti/endi/counti: the body
 * starts 12 bytes after lp.starti, its last instruction is 2 x 56 - 1 instructions later, so
 * 12 + 111 * 4 = 456 bytes after lp.starti, 452 bytes (226 half-words) after lp.endi. */
#define REG_GROUP                                                                              \
  GAP8_ASM_P_LW_POST_REG(R_Y, "%[w]", "%[p1]")   /* P(c+1, -1) */                              \
  GAP8_ASM_P_LW_POST_REG(R_Z1, "%[w]", "%[p0]")  /* P(c, -1) */                                \
  GAP8_ASM_P_LW_POST_REG(R_X, "%[w]", "%[pm]")   /* P(c-1, -1) */                              \
  GAP8_ASM_P_LW_POST_REG(R_H0, "%[w]", "%[p1]")  /* P(c+1, 0) */                               \
  GAP8_ASM_P_LW_POST_REG(R_Z0, "%[w]", "%[p0]")  /* P(c, 0) */                                 \
  GAP8_ASM_P_LW_POST_REG(R_G0, "%[w]", "%[pm]")  /* P(c-1, 0) */                               \
  REG_AVG(R_Y, R_Z1, R_Y)                 /* h(c, -1) */                                       \
  REG_AVG(R_X, R_X, R_Z1)                 /* h(c-1, -1) */                                     \
  REG_AVG(R_GG, R_Z1, R_Z0)               /* g(c, -1) */                                       \
  REG_AVG(R_H0, R_Z0, R_H0)               /* h(c, 0) */                                        \
  REG_AVG(R_G0, R_G0, R_Z0)               /* h(c-1, 0) */                                      \
  REG_AVG(R_DA, R_Y, R_H0)                /* d(c, -1) */                                       \
  REG_AVG(R_DB, R_X, R_G0)                /* d(c-1, -1) */                                     \
  ".Lstart%=: " GAP8_ASM_LP_STARTI("0", "6") GAP8_ASM_LP_ENDI("0", "226")                      \
  GAP8_ASM_LP_COUNTI("0", "4")                                                                 \
  ".Lbody%=: "                                                                                 \
  REG_ROW(R_H0, R_G0, R_Z0, R_X, R_Z1, R_Y)                                                    \
  REG_ROW(R_Y, R_X, R_Z1, R_G0, R_Z0, R_H0)                                                    \
  ".Lafter%=:\n\t"                                                                             \
  GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lbody%=", "12")                                       \
  GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lafter%=", "460")
/* clang-format on */

/* The eight half-pixel SADs of prev's block `blk` (row stride w): row0[e], e = 0..2, point at
 * next's word P(e - 1, -1) of group 0 (the matched block's column e - 1, row -1), each read with
 * a stride of w; group 1's words are 4 bytes further. */
static inline void half_sads_in_registers(const uint8_t *blk, const uint8_t *const row0[3],
                                          uint32_t w, uint32_t sub[8]) {
  const uint32_t one = 1;
  uint32_t acc0 = 0, acc1 = 0, acc2 = 0, acc3 = 0, acc4 = 0, acc5 = 0, acc6 = 0, acc7 = 0;
  for (uint32_t g = 0; g < 8; g += 4) {
    const uint8_t *pb = blk + g, *pm = row0[0] + g, *p0 = row0[1] + g, *p1 = row0[2] + g;
    __asm__ volatile(GAP8_ASM_HWLOOP_BEGIN REG_GROUP GAP8_ASM_HWLOOP_END
                     : [acc0] "+r"(acc0), [acc1] "+r"(acc1), [acc2] "+r"(acc2), [acc3] "+r"(acc3),
                       [acc4] "+r"(acc4), [acc5] "+r"(acc5), [acc6] "+r"(acc6), [acc7] "+r"(acc7),
                       [pb] "+r"(pb), [pm] "+r"(pm), [p0] "+r"(p0), [p1] "+r"(p1)
                     : [w] "r"(w), [one] "r"(one)
                     : HALF_REG_CLOBBERS, "memory");
  }
  sub[0] = acc0, sub[1] = acc1, sub[2] = acc2, sub[3] = acc3;
  sub[4] = acc4, sub[5] = acc5, sub[6] = acc6, sub[7] = acc7;
}

#endif
