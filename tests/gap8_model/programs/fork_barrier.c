/* Fork and barrier on every team size 1..cores: phase 2 reads a neighbour's phase-1 value, which
 * is only there if the barrier between the phases waited for every team member. Each core also
 * counts its own instructions over a known block: the counters are private to a core. */
#include "pmsis.h"

#define MAX_CORES 8

static volatile int stage1[MAX_CORES], stage2[MAX_CORES];
static volatile int rounds_seen[MAX_CORES];
static volatile unsigned instr_seen[MAX_CORES];

/* A loop of 5 + id rounds (2 instructions each) plus the stop store, so each core's count
 * differs. */
static void count_own_block(int id) {
  unsigned n = 5u + (unsigned)id;
  pi_perf_conf(1u << PI_PERF_INSTR);
  pi_perf_reset();
  __asm__ volatile(
      "li t0, %[start]\n li t1, %[stop]\n sw zero, 0(t0)\n"
      "1: addi %[n], %[n], -1\n bnez %[n], 1b\n"
      "sw zero, 0(t1)\n"
      : [n] "+r"(n)
      : [start] "i"(GAP8_PERF_START), [stop] "i"(GAP8_PERF_STOP)
      : "t0", "t1", "memory");
  instr_seen[id] = pi_perf_read(PI_PERF_INSTR);
}

static void body(void *arg) {
  const int id = pi_core_id(), n = pi_cl_team_nb_cores();
  stage1[id] = (int)arg + id;
  pi_cl_team_barrier();
  stage2[id] = stage1[(id + 1) % n] * 2;
  pi_cl_team_barrier();
  rounds_seen[id] = rounds_seen[id] + 1;
  count_own_block(id);
}

int main(void) {
  const int cores = pi_cl_cluster_nb_cores();
  for (int team = 1; team <= cores; ++team) {
    for (int i = 0; i < MAX_CORES; ++i) stage1[i] = stage2[i] = -1;
    pi_cl_team_fork(team, body, (void *)(team * 100));
    for (int id = 0; id < team; ++id) {
      if (stage2[id] != (team * 100 + (id + 1) % team) * 2) return 10 + team;
    }
    for (int id = team; id < MAX_CORES; ++id) {
      if (stage2[id] != -1) return 30 + team;
    }
    for (int id = 0; id < team; ++id) {
      if (instr_seen[id] != 2u * (5u + (unsigned)id) + 1u) return 70 + id;
    }
  }
  for (int id = 0; id < cores; ++id) {
    if (rounds_seen[id] != cores - id) return 50 + id;
  }
  printf("fork_barrier ok on %d cores\n", cores);
  return 0;
}
