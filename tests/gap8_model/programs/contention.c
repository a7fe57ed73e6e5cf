/* TCDM contention: every core of the team loads 200 times either from one shared word (one
 * bank: the cores collide) or from a word in its own bank (no collision). The host test reads
 * each core's TCDM_CONT and cycle counters. The host sets contention_mode (0 same bank, 1 own
 * bank, 2 mixed: even cores share one bank while odd cores use their own) before the run. */
#include "pmsis.h"

static volatile uint32_t words[16 * 8] PI_L1;
volatile uint32_t contention_mode = 7; /* in .data, so start-up code leaves it alone */

static void hammer(void *arg) {
  const int mode = (int)arg;
  const int own = mode == 1 || (mode == 2 && (pi_core_id() & 1));
  volatile uint32_t *w = own ? &words[pi_core_id()] : &words[0];
  uint32_t sum = 0;
  if (mode == 2) { /* 4 loads per iteration: the even cores keep colliding while odd ones run */
    for (int i = 0; i < 50; ++i) sum += w[0] + w[0] + w[0] + w[0];
  } else {
    for (int i = 0; i < 200; ++i) sum += *w;
  }
  words[16 + pi_core_id()] = sum;
}

int main(void) {
  if (contention_mode > 2) return 3;
  pi_cl_team_fork(0, hammer, (void *)contention_mode);
  return 0;
}
