/* Fork and barrier on every team size 1..cores: phase 2 reads a neighbour's phase-1 value, which
 * is only there if the barrier between the phases waited for every team member. */
#include "pmsis.h"

#define MAX_CORES 8

static volatile int stage1[MAX_CORES], stage2[MAX_CORES];
static volatile int rounds_seen[MAX_CORES];

static void body(void *arg) {
  const int id = pi_core_id(), n = pi_cl_team_nb_cores();
  stage1[id] = (int)arg + id;
  pi_cl_team_barrier();
  stage2[id] = stage1[(id + 1) % n] * 2;
  pi_cl_team_barrier();
  rounds_seen[id] = rounds_seen[id] + 1;
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
  }
  for (int id = 0; id < cores; ++id) {
    if (rounds_seen[id] != cores - id) return 50 + id;
  }
  printf("fork_barrier ok on %d cores\n", cores);
  return 0;
}
