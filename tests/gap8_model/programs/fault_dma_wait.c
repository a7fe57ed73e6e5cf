/* Waits for the DMA event with no transfer in flight, as plp_dma_wait's inner step
 * (eu_evt_maskWaitAndClr) would if the status read were skipped: nothing will raise it. (Waiting
 * on a counter that has nothing in flight returns at once, on GAP8 as in the model.) */
#include "pmsis.h"

int main(void) {
  __gap8_write(GAP8_EU_EVT_MASK_OR, 1u << GAP8_EVT_DMA);
  (void)__gap8_read(GAP8_EU_EVT_WAIT_CLEAR);
  return 0;
}
