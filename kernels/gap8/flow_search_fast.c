/* The integer search of the "fast" variant (beyond the paper): prev's 8x8 block is loaded once
 * per POI into 16 registers and reused by all (2S+1)^2 candidates, so each candidate loads only
 * next's 16 words: half the loads of flow_search.c, same SADs in the same order (bit-exact).
 * The 2S+1 candidates of one row of displacements are one asm block: a hardware loop over the
 * candidates, the 8 block rows unrolled in its body (the 16 words of prev are 16 registers, which
 * no loop can index), next read with post-increment loads. */
#include "search_raster.h"

/* clang-format off */
/* acc += 64 * USAD8(prev, v) (the key's scale, search_raster.h); v is overwritten. */
#define HELD_SAD(prev, v) SAD4_ACC_ASM("%[acc]", prev, v, "%[t]", v, "%[scale]")

/* Block row r: next's two words (the second load steps to the next row), two SADs against
 * prev's words lo and hi. The loads' values are used two instructions later at the earliest. */
#define HELD_ROW(lo, hi)                                \
  GAP8_ASM_P_LW_POST_IMM("%[v0]", "4", "%[pb]")         \
  GAP8_ASM_P_LW_POST_REG("%[v1]", "%[rest]", "%[pb]")   \
  HELD_SAD("%[p" #lo "]", "%[v0]")                      \
  HELD_SAD("%[p" #hi "]", "%[v1]")
/* clang-format on */

/* Candidates row, row+1, ..., row+n-1 of next (row stride w) against prev's block held in
 * p[0..15]: returns the smallest key 64 * SAD + index (search_raster.h). */
static uint32_t search_row_held(const uint32_t p[16], const uint8_t *row, uint32_t w,
                                uint32_t n) {
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

uint32_t flow_integer_search(const flow_ctx *c, const uint8_t *blk, uint32_t x, uint32_t y, int *bx,
                             int *by) {
  return search_raster(c, blk, x, y, bx, by, search_row_held);
}
