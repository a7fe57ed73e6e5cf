/* What the parts of the GAP8 flow kernel share: the run's context in L1 and the per-variant
 * hooks. One ELF per variant links flow_main.c, flow_poi.c and one half_<variant>.c. */
#ifndef PXFLOW_GAP8_FLOW_KERNEL_H
#define PXFLOW_GAP8_FLOW_KERNEL_H

#include <stdint.h>

#include "flow_abi.h"

typedef struct {
  uint32_t width, height, search_radius;
  uint32_t feature_threshold, sad_threshold;
  uint32_t cores, split;
  uint32_t pois;
  const uint8_t *prev, *next; /* L1 */
  uint8_t *planes[3];         /* L1: h, g, d of the whole next frame (global variant only) */
  const uint16_t *poi_xy;     /* L1: x, y of each POI in grid order */
  pxflow_poi_record *records; /* L1 */
} flow_ctx;

/* Number of full-frame planes the variant keeps in L1 (3 for global, else 0). */
extern const uint32_t variant_planes;

/* Runs on every team core before any POI; the global variant builds its planes here (and
 * synchronises the team itself). */
void variant_prepare(const flow_ctx *c, uint32_t core);

/* The eight half-pixel SADs of prev's block `blk` (row stride W) against the neighbourhood of
 * the matched 8x8 block of next, whose top-left corner is (mx, my). */
void variant_half_sads(const flow_ctx *c, const uint8_t *blk, uint32_t mx, uint32_t my,
                       uint32_t sub[8]);

/* SPEC §3 step 2: raster order over dy, dx in -S..S, strictly smaller SAD replaces. Returns the
 * best SAD and its displacement (flow_search.c, or flow_search_fast.c in the fast variant). */
uint32_t flow_integer_search(const flow_ctx *c, const uint8_t *blk, uint32_t x, uint32_t y, int *bx,
                             int *by);

/* The team's entry point: every POI of this core, as flow_poi.c computes it. */
void flow_team_entry(void *ctx);

/* Hooks with a plain default (weak, in flow_main.c): clearing `bytes` (a multiple of 4) of words
 * (the fast variant's does nothing: its team clears the records), and HF's V / Wt over bins
 * lo..hi (SPEC §5: accumulated in float, but exact; no variant replaces it any more). */
void flow_clear_words(void *dst, uint32_t bytes);
float flow_window_mean(const uint16_t *hist, int lo, int hi);

/* The fast variant's hooks (fast_serial.c), compiled in only where PXFLOW_GAP8_FAST_HOOKS is
 * defined (fast_main.c, fast_poi.c), so that the other variants' code stays byte for byte what it
 * was: after each accepted POI's record, on its core; every core at the end of the team's work;
 * SPEC §5 on core 0 after the join (else flow_main.c's, the spec core's in soft-float). */
#ifdef PXFLOW_GAP8_FAST_HOOKS
void variant_accepted(const flow_ctx *c, const pxflow_poi_record *rec);
void variant_finish(const flow_ctx *c, uint32_t core);
void flow_estimate(const pxflow_poi_record *records, uint32_t pois, const pxflow_gap8_params *p,
                   pxflow_gap8_result *out);
#endif

#endif
