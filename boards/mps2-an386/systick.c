/* SysTick (ARMv7-M ARM, ARM DDI 0403E, B3.3 "The system timer, SysTick"): a 24-bit down counter.
 * SYST_CSR 0xE000E010 (bit 0 ENABLE, bit 1 TICKINT, bit 2 CLKSOURCE = processor clock, bit 16
 * COUNTFLAG), SYST_RVR 0xE000E014 (reload), SYST_CVR 0xE000E018 (current; any write clears it).
 * The counter runs from 0xFFFFFF down to 0 and reloads; the SysTick exception counts the wraps,
 * so ticks = wraps * 2^24 + (0xFFFFFF - CVR). The DWT cycle counter would be the natural choice
 * on silicon but reads 0 under QEMU (docs/cortex-m4.md). */
#include "board.h"

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define ICSR (*(volatile uint32_t *)0xE000ED04u)
#define ICSR_PENDSTSET (1u << 26)

#define CSR_ENABLE (1u << 0)
#define CSR_TICKINT (1u << 1)
#define CSR_CLKSOURCE (1u << 2)

#define SYSTICK_MAX 0xFFFFFFu

static volatile uint32_t wraps;

void m4_systick_handler(void) { ++wraps; }

void board_systick_init(void) {
  SYST_RVR = SYSTICK_MAX;
  SYST_CVR = 0; /* clears the counter and COUNTFLAG */
  wraps = 0;
  SYST_CSR = CSR_ENABLE | CSR_TICKINT | CSR_CLKSOURCE;
  /* CVR holds the 0 written above until the first clock loads RVR (B3.3.1: a reload, not a wrap
   * to 0, so no exception): wait for it, or the first reading would be 2^24 - 1 ahead. */
  while (SYST_CVR == 0) {
  }
}

uint64_t board_systick_ticks(void) {
  /* With interrupts masked, a wrap that happened since the last SysTick exception shows as
   * ICSR.PENDSTSET (0xE000ED04 bit 26, DDI 0403E B3.2.4): count it, and read CVR again, as the
   * first read may be from before the reload (the next wrap is 2^24 ticks away). */
  __asm__ volatile("cpsid i" ::: "memory");
  uint32_t w = wraps;
  uint32_t now = SYST_CVR;
  if (ICSR & ICSR_PENDSTSET) {
    now = SYST_CVR;
    ++w;
  }
  __asm__ volatile("cpsie i" ::: "memory");
  return ((uint64_t)w << 24) + (SYSTICK_MAX - now);
}
