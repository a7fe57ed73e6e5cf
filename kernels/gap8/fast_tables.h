/* The fast variant's per-frame tables (beyond the paper), built by the team in variant_prepare
 * before any POI (fast_tables.c) and read by its integer search (flow_search_fast.c):
 *  - copy[q], q = 0..3: next shifted left by q bytes (copy[0] is next itself), so that the
 *    candidate block at any pixel offset o is read with word-aligned loads from copy[o & 3];
 *  - neg_box[y * W + x] = -(sum of next's 8x8 block at (x, y)), for every candidate position
 *    of the grid's search windows (other entries are not written).
 * With them the SAD of a candidate is 2 * sum(max(a, b)) - A - B (A the sum of prev's block, B
 * of the candidate's): two Xpulp instructions per 4 pixels (pv.maxu.b, pv.sdotup.sc.b) instead
 * of four. Used only when W is kFastWidth (the search uses immediate row offsets) and the tables
 * fit L1; otherwise `ready` is 0 and the search takes the held-register path. */
#ifndef PXFLOW_GAP8_FAST_TABLES_H
#define PXFLOW_GAP8_FAST_TABLES_H

#include <pmsis.h>
#include <stdint.h>

#include "flow_kernel.h"

enum { kFastWidth = 64 };

typedef struct {
  uint32_t ready; /* the tables of the current frame are built */
  uint32_t tried; /* the L1 allocation was attempted (once per run) */
  const uint8_t *copy[4];
  uint32_t *neg_box;
} fast_tables;

/* In L1 (PI_L1 data): read by every core for every POI. */
extern fast_tables g_fast;

/* Every core first, at the start of the fork (fast_serial.c): its share of the records cleared,
 * its histogram row and sums zeroed. The callers' next barrier orders it before any POI. */
void fast_team_begin(const flow_ctx *c, uint32_t core);

/* A team barrier that is also a compiler barrier: pmsis.h's is a volatile register read, across
 * which GCC may move ordinary loads (of g_fast, of the tables and histograms other cores wrote). */
static inline void team_sync(void) {
  pi_cl_team_barrier();
  __asm__ volatile("" ::: "memory");
}

#endif
