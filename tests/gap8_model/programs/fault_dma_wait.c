/* Waits for a DMA transfer that was never queued. */
#include "pmsis.h"

int main(void) {
  pi_cl_dma_cmd_t cmd = {.id = 42};
  pi_cl_dma_cmd_wait(&cmd);
  return 0;
}
