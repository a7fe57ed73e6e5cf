/* The integer search of the "fast" variant (beyond the paper). Two paths, the same records:
 *
 * The algebra path (W = 64 and the tables of fast_tables.h in L1): |a - b| = 2 max(a, b) - a - b,
 * so SAD = 2 M - A - B with M = sum of max(a, b) (pv.maxu.b, then pv.sdotup.sc.b with the scalar
 * 2: two instructions per 4 pixels), A the sum of prev's block (once per POI) and B the
 * candidate's block sum (the table, -B loaded as the accumulator's start). Each candidate reads
 * its 16 words aligned from the shifted copy of next that matches its alignment, so the
 * candidates are taken in four groups by dx mod 4, all in one asm block (prev's words loaded
 * once per POI): per group, hardware loop 1 over pairs of rows of displacements, loop 0 over
 * the group's candidates in a row, two at a time, (dx, dy) and (dx, dy + 1), which share 7 of
 * the 9 rows of next they read (18 loads for two candidates instead of 32); then the last row
 * (2S + 1 is odd) one candidate at a time. No branch in any loop: the best is kept by p.minu on
 * the key (SAD + A) << 16 | (the candidate's table address, low 16 bits): the smallest SAD, then
 * the smallest table address, i.e. the first candidate in raster order (the address grows with
 * (y + dy) * W + x + dx), whatever the order in which the candidates are searched. SAD + A <
 * 2^15 and the table lies in L1 (64 KiB), so the key never wraps.
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

/* The algebra path's registers are fixed (the asm names 27 of them, more than GCC can allocate
 * to operands): prev's 16 words in s0..s11, t3..t6; next's two words v0, v1 and a scratch t; the
 * accumulators of the pair's two candidates; the candidate pointer pb and the table pointer pt;
 * loop 0's count n and the steps of pb and pt from a pair of rows to the next. key (a0) is an
 * operand, the group list's cursor lives in memory. */
#define P_(k) P_##k
#define P_0 "s0"
#define P_1 "s1"
#define P_2 "s2"
#define P_3 "s3"
#define P_4 "s4"
#define P_5 "s5"
#define P_6 "s6"
#define P_7 "s7"
#define P_8 "s8"
#define P_9 "s9"
#define P_10 "s10"
#define P_11 "s11"
#define P_12 "t3"
#define P_13 "t4"
#define P_14 "t5"
#define P_15 "t6"
#define R_V0 "t0"
#define R_V1 "t1"
#define R_T "a7"
#define R_ACC "t2"
#define R_ACCB "a1"
#define R_PB "a2"
#define R_PT "a3"
#define R_N "a4"
#define R_PB_ROW "a5"
#define R_PT_ROW "a6"
#define ALGEBRA_CLOBBERS                                                                      \
  "s0", "s1", "s2", "s3", "s4", "s5", "s6", "s7", "s8", "s9", "s10", "s11", "t3", "t4", "t5", \
      "t6", "t0", "t1", "t2", "a1", "a3", "a4", "a5", "a6", "a7"

/* clang-format off */
/* acc += imm * (sum of v's bytes): pv.sdotup.sci.b (funct6 0x28, .sci.b), no scalar register. */
#define SDOT_IMM(acc, v, imm) GAP8_ASM_PV_SCI("0x28", "7", acc, v, imm)
/* acc += 2 * sum(max(v, prev word p)), v overwritten. */
#define MAX2(acc, v, p) GAP8_ASM_PV_MAXU_B(v, v, p) SDOT_IMM(acc, v, "2")
/* The same into t, v kept (a word of next that two candidates compare). */
#define MAX2_KEEP(acc, v, p) GAP8_ASM_PV_MAXU_B(R_T, v, p) SDOT_IMM(acc, R_T, "2")
/* Next's two words of block row r of the candidate (r >= 1; W = 64, immediate offsets from pb,
 * which the first load of row 0 has advanced by 4). */
#define NEXT_ROW(r)                                                                            \
  "lw " R_V0 ", 64*" #r "-4(" R_PB ")\n\t"                                                     \
  "lw " R_V1 ", 64*" #r "(" R_PB ")\n\t"
#define NEXT_ROW0                                                                              \
  GAP8_ASM_P_LW_POST_IMM(R_V0, "4", R_PB)                                                      \
  "lw " R_V1 ", 0(" R_PB ")\n\t"
/* Row k of next, 1 <= k <= 7, compared twice: with prev's row k (candidate A at dy) and row k-1
 * (candidate B at dy + 1). */
#define PAIR_ROW(k, a_lo, a_hi, b_lo, b_hi)                                                    \
  NEXT_ROW(k)                                                                                  \
  MAX2_KEEP(R_ACC, R_V0, P_(a_lo)) MAX2(R_ACCB, R_V0, P_(b_lo))                                \
  MAX2_KEEP(R_ACC, R_V1, P_(a_hi)) MAX2(R_ACCB, R_V1, P_(b_hi))
/* Row r of one candidate. */
#define ONE_ROW(r, lo, hi) NEXT_ROW(r) MAX2(R_ACC, R_V0, P_(lo)) MAX2(R_ACC, R_V1, P_(hi))
/* The key (SAD + A) << 16 | table address (+16) and its minimum. */
#define KEY_MIN(acc)                                                                           \
  "slli " acc ", " acc ", 16\n\t"                                                              \
  "add " acc ", " acc ", " R_PT "\n\t" P_MINU_ASM("%[key]", "%[key]", acc)
/* prev's words of block row r (any alignment: RI5CY splits a misaligned lw). */
#define PREV_ROW(r, lo, hi)                                                                    \
  "lw " P_(lo) ", 64*" #r "(" R_PB ")\n\t"                                                     \
  "lw " P_(hi) ", 64*" #r "+4(" R_PB ")\n\t"
#define PREV_SUM(lo, hi) SDOT_IMM(R_ACC, P_(lo), "1") SDOT_IMM(R_ACC, P_(hi), "1")
/* clang-format on */

/* One group of candidates (same column mod 4, so the same shifted copy): the rows of
 * displacements in pairs (`pairs` = S of them) and then the last one alone, n candidates per row
 * 4 pixels apart. pb = the first candidate in its aligned copy, pt = its entry of neg_box; after
 * a pair of rows, pb and pt step to the next pair's first. */
typedef struct {
  const uint8_t *pb;
  const uint32_t *pt;
  uint32_t n, pairs, pb_step, pt_step;
} search_group;

/* The groups of one POI, ended by pb = 0 (at most 4 and the end), and A (the byte sum of prev's
 * block), which the asm writes before it reads the groups. */
typedef struct {
  search_group groups[5];
  uint32_t a;
} search_plan;

/* The 16 words of prev's block at blk into registers, A into plan->a, then every group of the
 * plan searched with prev's words held: returns the smallest key. A pair of candidates (dx, dy)
 * and (dx, dy + 1) reads the 9 rows of next they span once: 18 loads instead of 32. */
static uint32_t search_groups(const uint8_t *blk, search_plan *plan) {
  register uint32_t key __asm__("a0") = 0xFFFFFFFFu;
  register const uint8_t *pb __asm__("a2") = blk;
  const search_group *cursor = plan->groups;
  /* clang-format off */
  __asm__ volatile(
      PREV_ROW(0, 0, 1) PREV_ROW(1, 2, 3) PREV_ROW(2, 4, 5) PREV_ROW(3, 6, 7)
      PREV_ROW(4, 8, 9) PREV_ROW(5, 10, 11) PREV_ROW(6, 12, 13) PREV_ROW(7, 14, 15)
      "li " R_ACC ", 0\n\t"
      PREV_SUM(0, 1) PREV_SUM(2, 3) PREV_SUM(4, 5) PREV_SUM(6, 7)
      PREV_SUM(8, 9) PREV_SUM(10, 11) PREV_SUM(12, 13) PREV_SUM(14, 15)
      "sw " R_ACC ", %[a]\n\t"
      ".Lgroup%=:\n\t"
      "lw " R_T ", %[cursor]\n\t"
      "lw " R_PB ", 0(" R_T ")\n\t"
      "lw " R_PT ", 4(" R_T ")\n\t"
      "lw " R_N ", 8(" R_T ")\n\t"
      "lw " R_ACC ", 12(" R_T ")\n\t"
      "lw " R_PB_ROW ", 16(" R_T ")\n\t"
      "lw " R_PT_ROW ", 20(" R_T ")\n\t"
      "addi " R_T ", " R_T ", 24\n\t"
      "sw " R_T ", %[cursor]\n\t"
      "beqz " R_PB ", .Ldone%=\n\t"
      GAP8_ASM_HWLOOP_BEGIN
      /* loop 1 over the pairs of rows: lp.setup 0, loop 0's 91 instructions, two pointer steps;
       * the last 376 bytes after lp.setup. Loop 0 over the pairs of candidates: the two -B, row 0
       * (A only), rows 1..7 (both), row 8 (B only), the two keys; the last 364 bytes after its
       * lp.setup. */
      ".Lrows%=: " GAP8_ASM_LP_SETUP("1", R_ACC, "188")
      ".Lcand%=: " GAP8_ASM_LP_SETUP("0", R_N, "182")
      GAP8_ASM_P_LW_POST_IMM(R_ACC, "16", R_PT)          /* A's -B; pt to the next candidate */
      "lw " R_ACCB ", 256-16(" R_PT ")\n\t"              /* B's -B, one table row below */
      NEXT_ROW0 MAX2(R_ACC, R_V0, P_0) MAX2(R_ACC, R_V1, P_1)
      PAIR_ROW(1, 2, 3, 0, 1) PAIR_ROW(2, 4, 5, 2, 3) PAIR_ROW(3, 6, 7, 4, 5)
      PAIR_ROW(4, 8, 9, 6, 7) PAIR_ROW(5, 10, 11, 8, 9) PAIR_ROW(6, 12, 13, 10, 11)
      PAIR_ROW(7, 14, 15, 12, 13)
      NEXT_ROW(8) MAX2(R_ACCB, R_V0, P_14) MAX2(R_ACCB, R_V1, P_15)
      KEY_MIN(R_ACC)
      "slli " R_ACCB ", " R_ACCB ", 16\n\t"
      "add " R_ACCB ", " R_ACCB ", " R_PT "\n\t"
      "addi " R_ACCB ", " R_ACCB ", 256\n\t"               /* B's entry: a table row below */
      ".Lcand_end%=: " P_MINU_ASM("%[key]", "%[key]", R_ACCB)
      "add " R_PB ", " R_PB ", " R_PB_ROW "\n\t"
      ".Lrows_end%=: add " R_PT ", " R_PT ", " R_PT_ROW "\n\t"
      /* the last row of displacements: loop 0 over its candidates, one at a time (-B, the 8
       * rows, the key); the last 208 bytes after lp.setup */
      ".Lone%=: " GAP8_ASM_LP_SETUP("0", R_N, "104")
      GAP8_ASM_P_LW_POST_IMM(R_ACC, "16", R_PT)
      NEXT_ROW0 MAX2(R_ACC, R_V0, P_0) MAX2(R_ACC, R_V1, P_1)
      ONE_ROW(1, 2, 3) ONE_ROW(2, 4, 5) ONE_ROW(3, 6, 7) ONE_ROW(4, 8, 9)
      ONE_ROW(5, 10, 11) ONE_ROW(6, 12, 13) ONE_ROW(7, 14, 15)
      "slli " R_ACC ", " R_ACC ", 16\n\t"
      "add " R_ACC ", " R_ACC ", " R_PT "\n\t"
      ".Lone_end%=: " P_MINU_ASM("%[key]", "%[key]", R_ACC)
      GAP8_ASM_CHECK_DISTANCE(".Lcand%=", ".Lcand_end%=", "364")
      GAP8_ASM_CHECK_DISTANCE(".Lrows%=", ".Lrows_end%=", "376")
      GAP8_ASM_CHECK_DISTANCE(".Lone%=", ".Lone_end%=", "208")
      GAP8_ASM_HWLOOP_END "\n\t"
      "j .Lgroup%=\n\t"
      ".Ldone%=:\n\t"
      : [key] "+r"(key), "+r"(pb), [cursor] "+m"(cursor), [a] "=m"(plan->a)
      : "m"(*plan)
      : ALGEBRA_CLOBBERS, "memory");
  /* clang-format on */
  return key;
}

static uint32_t algebra_search(const flow_ctx *c, const uint8_t *blk, uint32_t x, uint32_t y,
                               int *bx, int *by) {
  const uint32_t s = c->search_radius, w = kFastWidth;
  const uint32_t o0 = (y - s) * w + x - s; /* the first candidate's pixel offset */
  search_plan plan;
  uint32_t j = 0;
  for (; j < 4 && j <= 2 * s; ++j) {
    const uint32_t o = o0 + j, q = o & 3, n = (2 * s - j) / 4 + 1;
    plan.groups[j] = (search_group){g_fast.copy[q] + (o - q), g_fast.neg_box + o,     n, s,
                                    2 * kFastWidth - 4 * n,   8 * kFastWidth - 16 * n};
  }
  plan.groups[j].pb = 0;
  const uint32_t key = search_groups(blk, &plan);
  const uint32_t a = plan.a;
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
