/* Cluster DMA: 1-D L2 -> L1 (asynchronous: the bytes are not there before the wait), 2-D tile
 * gather, L1 -> L2, and one transfer per core of a team in parallel. */
#include "pmsis.h"

#define N 1024
#define IMAGE_W 64

static uint8_t src[N];
static uint8_t back[N];
static uint8_t image[IMAGE_W * 32];
static uint8_t *l1;
static volatile int team_errors;

static void per_core_copy(void *arg) {
  (void)arg;
  const int id = pi_core_id(), n = pi_cl_team_nb_cores();
  const uint32_t chunk = N / n;
  pi_cl_dma_cmd_t cmd;
  pi_cl_dma_cmd((uint32_t)(src + id * chunk), (uint32_t)(l1 + id * chunk), chunk,
                PI_CL_DMA_DIR_EXT2LOC, &cmd);
  pi_cl_dma_cmd_wait(&cmd);
  for (uint32_t i = 0; i < chunk; ++i) {
    if (l1[id * chunk + i] != src[id * chunk + i]) team_errors = team_errors + 1;
  }
}

int main(void) {
  for (int i = 0; i < N; ++i) src[i] = (uint8_t)(i * 7 + 3);
  for (int i = 0; i < IMAGE_W * 32; ++i) image[i] = (uint8_t)(i ^ (i >> 6));
  l1 = pi_cl_l1_malloc(0, N);
  if (!l1) return 2;

  pi_cl_dma_copy_t copy = {
      .ext = (uint32_t)src, .loc = (uint32_t)l1, .size = N, .dir = PI_CL_DMA_DIR_EXT2LOC};
  pi_perf_conf(1u << PI_PERF_CYCLES | 1u << PI_PERF_ACTIVE_CYCLES);
  pi_perf_reset();
  pi_perf_start();
  pi_cl_dma_memcpy(&copy);
  const int early = ((volatile uint8_t *)l1)[N - 1];
  pi_cl_dma_wait(&copy);
  pi_perf_stop();
  if (early != 0) return 3; /* asynchronous: the last byte cannot have arrived yet */
  for (int i = 0; i < N; ++i) {
    if (l1[i] != src[i]) return 4;
  }
  const unsigned cycles = pi_perf_read(PI_PERF_CYCLES),
                 active = pi_perf_read(PI_PERF_ACTIVE_CYCLES);
  if (cycles < 2 + N / 8) return 5; /* mchan: first burst 2 cycles on, 8 bytes per cycle */
  if (active >= cycles) return 6;   /* the core slept during the wait */

  /* 2-D: a 16 x 8 tile at (5, 3) of the 64-wide image, packed in L1. */
  pi_cl_dma_copy_2d_t tile = {.ext = (uint32_t)(image + 3 * IMAGE_W + 5),
                              .loc = (uint32_t)l1,
                              .size = 16 * 8,
                              .dir = PI_CL_DMA_DIR_EXT2LOC,
                              .stride = IMAGE_W,
                              .length = 16};
  pi_cl_dma_memcpy_2d(&tile);
  pi_cl_dma_wait(&tile);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 16; ++x) {
      if (l1[y * 16 + x] != image[(y + 3) * IMAGE_W + x + 5]) return 7;
    }
  }

  /* L1 -> L2. */
  for (int i = 0; i < N; ++i) l1[i] = (uint8_t)(255 - i);
  pi_cl_dma_copy_t out = {
      .ext = (uint32_t)back, .loc = (uint32_t)l1, .size = N, .dir = PI_CL_DMA_DIR_LOC2EXT};
  pi_cl_dma_memcpy(&out);
  pi_cl_dma_wait(&out);
  for (int i = 0; i < N; ++i) {
    if (back[i] != (uint8_t)(255 - i)) return 8;
  }

  /* Every core of the team moves its own chunk. */
  for (int i = 0; i < N; ++i) l1[i] = 0;
  pi_cl_team_fork(0, per_core_copy, 0);
  if (team_errors != 0) return 9;
  printf("dma ok: %u cycles for %d bytes, %u active\n", cycles, N, active);
  return 0;
}
