/* A DMA transfer whose L1 side runs past the end of L1. */
#include "pmsis.h"

int main(void) {
  pi_cl_dma_cmd_t cmd;
  pi_cl_dma_cmd(GAP8_L2_BASE, GAP8_L1_BASE + GAP8_L1_SIZE - 16, 64, PI_CL_DMA_DIR_EXT2LOC, &cmd);
  pi_cl_dma_cmd_wait(&cmd);
  return 0;
}
