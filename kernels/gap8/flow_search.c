/* The integer search of SPEC §3 step 2 as the firmware writes it: for each candidate, the 8x8
 * SAD reloads both blocks (16 words of prev, 16 of next), as compute_sad_8x8 does. Used by the
 * paper's three variants. The 2S+1 candidates of one row of displacements are one asm block with
 * two RI5CY hardware loops (candidates outside, the 8 block rows inside) and post-increment
 * loads, as the GAP SDK's compiler would emit: no loop counters, compares or pointer updates.
 * prev's block is first copied to a word-aligned buffer (the POIs sit at odd x, so each of its
 * words would otherwise be a misaligned, two-access load for every candidate). */
#include "search_raster.h"

/* Candidates cand, cand+1, ..., cand+n-1 of next (row stride w) against prev's block, packed
 * in `blk` (16 words, row by row). A SAD strictly smaller than *best replaces it; returns the
 * candidate of the last replacement, or 0 if none. One 4-byte SAD is maxu, minu, sub, sdotup
 * (flow_simd.h). */
static const uint8_t *search_row(const uint32_t *blk, const uint8_t *cand, uint32_t w, uint32_t n,
                                 uint32_t *best) {
  const uint8_t *hit = 0, *pb;
  const uint32_t *pa;
  uint32_t b = *best, acc, a0, a1, b0, b1, t0, t1, u0, u1;
  const uint32_t row_rest = w - 4, one = 1; /* next: p.lw x, 4(p!) then p.lw y, row_rest(p!) */
  __asm__ volatile(
      GAP8_ASM_HWLOOP_BEGIN
      "j .Lcand%=\n\t"
      /* a new best (rare: out of the loop's straight path) */
      ".Lbetter%=: mv %[b], %[acc]\n\t"
      "mv %[hit], %[cand]\n\t"
      "j .Lcand_end%=\n\t"
      /* loop 1 over the n candidates: 18 instructions after the set-up, the last at 72 bytes */
      ".Lcand%=: " GAP8_ASM_LP_SETUP("1", "%[n]", "36")
      "mv %[pa], %[blk]\n\t"
      "mv %[pb], %[cand]\n\t"
      "li %[acc], 0\n\t"
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
      GAP8_ASM_PV_SDOTUP_SC_B("%[acc]", "%[t0]", "%[one]")
      ".Lrow_end%=: " GAP8_ASM_PV_SDOTUP_SC_B("%[acc]", "%[t1]", "%[one]")
      /* bltu acc, b, .Lbetter (rare: taken only on a new best); .insn: always 4 bytes */
      ".insn b 0x63, 6, %[acc], %[b], .Lbetter%=\n\t"
      ".Lcand_end%=: addi %[cand], %[cand], 1\n\t"
      GAP8_ASM_CHECK_DISTANCE(".Lrow%=", ".Lrow_end%=", "48")
      GAP8_ASM_CHECK_DISTANCE(".Lcand%=", ".Lrow_end%=", "64") /* + bltu + addi = 72 */
      GAP8_ASM_HWLOOP_END
      : [b] "+r"(b), [hit] "+r"(hit), [cand] "+r"(cand), [pa] "=&r"(pa), [pb] "=&r"(pb),
        [acc] "=&r"(acc), [a0] "=&r"(a0), [a1] "=&r"(a1), [b0] "=&r"(b0), [b1] "=&r"(b1),
        [t0] "=&r"(t0), [t1] "=&r"(t1), [u0] "=&r"(u0), [u1] "=&r"(u1)
      : [n] "r"(n), [blk] "r"(blk), [rest] "r"(row_rest), [one] "r"(one)
      : "memory");
  *best = b;
  return hit;
}

uint32_t flow_integer_search(const flow_ctx *c, const uint8_t *blk, uint32_t x, uint32_t y, int *bx,
                             int *by) {
  return search_raster(c, blk, x, y, bx, by, search_row);
}
