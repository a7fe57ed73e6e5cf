/* Core 0 waits at a barrier for a team of every core, but the others were never forked. */
#include "pmsis.h"

int main(void) {
  pi_cl_team_barrier();
  return 0;
}
