/* The fast variant's serial parts on core 0 (beyond the paper), replacing the weak defaults of
 * flow_main.c (flow_kernel.h). */
#include "flow_kernel.h"
#include "flow_simd.h"

/* The records cleared by a hardware loop of post-increment stores, one cycle per word (GCC's
 * loop in flow_main.c takes a store, an add and a taken branch per word). */
void flow_clear_words(void *dst, uint32_t bytes) {
  const uint32_t n = bytes / 4;
  if (n < 3) { /* the loop body below is one instruction; RI5CY wants at least 3 */
    for (uint32_t k = 0; k < n; ++k) ((volatile uint32_t *)dst)[k] = 0;
    return;
  }
  uint8_t *p = dst;
  /* Three stores per iteration (RI5CY: at least 3 instructions per body), the rest after. */
  const uint32_t triples = n / 3;
  /* clang-format off */
  __asm__ volatile(
      GAP8_ASM_HWLOOP_BEGIN
      /* loop 0: body of 3 instructions, the last 12 bytes (6 half-words) after lp.setup */
      ".Lstart%=: " GAP8_ASM_LP_SETUP("0", "%[n]", "6")
      GAP8_ASM_P_SW_POST_IMM("x0", "4", "%[p]")
      GAP8_ASM_P_SW_POST_IMM("x0", "4", "%[p]")
      ".Lend%=: " GAP8_ASM_P_SW_POST_IMM("x0", "4", "%[p]")
      GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lend%=", "12")
      GAP8_ASM_HWLOOP_END
      : [p] "+r"(p)
      : [n] "r"(triples)
      : "memory");
  /* clang-format on */
  for (uint32_t k = 0; k < n - 3 * triples; ++k) ((volatile uint32_t *)p)[k] = 0;
}

/* V and Wt summed in integers (at most 127 * 5 * 64 and 64 here: exact in float, so each float
 * partial sum of the default equals the integer one) and converted once: the same bits. */
float flow_window_mean(const uint16_t *hist, int lo, int hi) {
  int value = 0, weight = 0;
  for (int b = lo; b <= hi; ++b) {
    value += b * hist[b];
    weight += hist[b];
  }
  return (float)value / (float)weight;
}
