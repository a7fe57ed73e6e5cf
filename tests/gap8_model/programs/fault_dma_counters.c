/* Allocates a 17th DMA counter without freeing any: mchan has 16 (GVSOC would stall the core
 * until another frees one; the model stops the run with a fault). A transfer larger than the
 * 16-bit size field is refused instead when dma_fault_mode is 1. */
#include "pmsis.h"

volatile uint32_t dma_fault_mode = 7; /* non-zero, so in .data: the host may set it to 1 */
static uint8_t big[70000 / 8];

int main(void) {
  if (dma_fault_mode == 1) {
    pi_cl_dma_cmd_t cmd;
    pi_cl_dma_cmd((uint32_t)big, GAP8_L1_BASE, 70000, PI_CL_DMA_DIR_EXT2LOC, &cmd);
    pi_cl_dma_cmd_wait(&cmd);
    return 0;
  }
  for (int i = 0; i < 17; ++i) (void)__gap8_read(GAP8_DMA_QUEUE);
  return 0;
}
