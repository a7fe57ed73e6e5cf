/* The benchmark load of bench.c split over every core of the cluster (rows by core id), to
 * measure the simulator with all cores busy and contending for TCDM banks. */
#include "pmsis.h"

#define W 64

static uint8_t a[W * W] PI_L1;
static uint8_t b[W * W] PI_L1;
static uint32_t best_of[8];

static uint32_t sad8x8(const uint8_t *p, const uint8_t *q) {
  uint32_t s = 0;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const int d = p[y * W + x] - q[y * W + x];
      s += d < 0 ? -d : d;
    }
  }
  return s;
}

static void rows(void *arg) {
  (void)arg;
  const int id = pi_core_id(), n = pi_cl_team_nb_cores();
  uint32_t best = 0xFFFFFFFFu;
  for (int round = 0; round < 40; ++round) {
    for (int y = 2 * id; y + 8 <= W; y += 2 * n) {
      for (int x = 0; x + 8 <= W; x += 2) {
        const uint32_t s = sad8x8(&a[y * W + x], &b[((y + round) % 56) * W + x]);
        if (s < best) best = s;
      }
    }
  }
  best_of[id] = best;
}

int main(void) {
  for (int i = 0; i < W * W; ++i) {
    a[i] = (uint8_t)(i * 13 + (i >> 6));
    b[i] = (uint8_t)(i * 7 + 1);
  }
  pi_cl_team_fork(0, rows, 0);
  uint32_t best = 0xFFFFFFFFu;
  for (int i = 0; i < pi_cl_cluster_nb_cores(); ++i) best = best_of[i] < best ? best_of[i] : best;
  printf("bench best %u\n", best);
  return 0;
}
