/* The integer search of SPEC §3 step 2 as the firmware writes it: for each candidate, the 8x8
 * SAD reloads both blocks (16 words of prev, 16 of next), as compute_sad_8x8 does. Used by the
 * paper's three variants. The 2S+1 candidates of one row of displacements are one asm block with
 * two RI5CY hardware loops (candidates outside, the 8 block rows inside) and post-increment
 * loads, as the GAP SDK's compiler would emit: no loop counters, compares or pointer updates.
 * prev's block is first copied to a word-aligned buffer (the POIs sit at odd x, so each of its
 * words would otherwise be a misaligned, two-access load for every candidate). */
#include "search_raster.h"

/* Candidates row, row+1, ..., row+n-1 of next (row stride w) against prev's block, packed in
 * `blk` (16 words, row by row): returns the smallest key 64 * SAD + index (search_raster.h). One
 * 4-byte SAD is maxu, minu, sub, sdotup (flow_simd.h), here with the scalar 64. */
static uint32_t search_row(const uint32_t *blk, const uint8_t *row, uint32_t w, uint32_t n) {
  const uint8_t *cand = row, *pb;
  const uint32_t *pa;
  uint32_t key = 0xFFFFFFFFu, acc, a0, a1, b0, b1, t0, t1, u0, u1;
  const uint32_t row_rest = w - 4, scale = kKeyScale; /* next: p.lw x, 4(p!), p.lw y, rest(p!) */
  /* clang-format off */
  __asm__ volatile(
      GAP8_ASM_HWLOOP_BEGIN
      /* loop 1 over the n candidates: 18 instructions after the set-up, the last at 72 bytes;
       * no branch in it (search_raster.h) */
      ".Lcand%=: " GAP8_ASM_LP_SETUP("1", "%[n]", "36")
      "mv %[pa], %[blk]\n\t"
      "mv %[pb], %[cand]\n\t"
      "sub %[acc], %[cand], %[row]\n\t" /* the candidate's index dx + S: the key's low bits */
      /* loop 0 over the 8 block rows: 12 instructions after the set-up, the last at 48 bytes */
      ".Lrow%=: " GAP8_ASM_LP_SETUPI("0", "8", "24")
      GAP8_ASM_P_LW_POST_IMM("%[a0]", "4", "%[pa]")
      GAP8_ASM_P_LW_POST_IMM("%[b0]", "4", "%[pb]")
      GAP8_ASM_P_LW_POST_IMM("%[a1]", "4", "%[pa]")
      GAP8_ASM_P_LW_POST_REG("%[b1]", "%[rest]", "%[pb]")
      GAP8_ASM_PV_MAXU_B("%[t0]", "%[a0]", "%[b0]")
      GAP8_ASM_PV_MINU_B("%[u0]", "%[a0]", "%[b0]")
      GAP8_ASM_PV_MAXU_B("%[t1]", "%[a1]", "%[b1]")
      GAP8_ASM_PV_MINU_B("%[u1]", "%[a1]", "%[b1]")
      GAP8_ASM_PV_SUB_B("%[t0]", "%[t0]", "%[u0]")
      GAP8_ASM_PV_SUB_B("%[t1]", "%[t1]", "%[u1]")
      GAP8_ASM_PV_SDOTUP_SC_B("%[acc]", "%[t0]", "%[scale]")
      ".Lrow_end%=: " GAP8_ASM_PV_SDOTUP_SC_B("%[acc]", "%[t1]", "%[scale]")
      P_MINU_ASM("%[key]", "%[key]", "%[acc]")
      "addi %[cand], %[cand], 1\n\t"
      ".Lcand_end%=:\n\t"
      GAP8_ASM_CHECK_DISTANCE(".Lrow%=", ".Lrow_end%=", "48")
      GAP8_ASM_CHECK_DISTANCE(".Lcand%=", ".Lcand_end%=", "76") /* last at 72 */
      GAP8_ASM_HWLOOP_END
      : [key] "+&r"(key), [cand] "+&r"(cand), [pa] "=&r"(pa), [pb] "=&r"(pb), [acc] "=&r"(acc),
        [a0] "=&r"(a0), [a1] "=&r"(a1), [b0] "=&r"(b0), [b1] "=&r"(b1), [t0] "=&r"(t0),
        [t1] "=&r"(t1), [u0] "=&r"(u0), [u1] "=&r"(u1)
      : [n] "r"(n), [blk] "r"(blk), [row] "r"(row), [rest] "r"(row_rest), [scale] "r"(scale)
      : "memory");
  /* clang-format on */
  return key;
}

uint32_t flow_integer_search(const flow_ctx *c, const uint8_t *blk, uint32_t x, uint32_t y, int *bx,
                             int *by) {
  return search_raster(c, blk, x, y, bx, by, search_row);
}
