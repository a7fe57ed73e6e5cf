/* The per-POI kernel of SPEC §3 on one cluster core: the shared one (pxflow_spec/poi_kernel.h:
 * feature test, integer search, half-pixel refinement, record) with this target's primitives
 * (flow_simd.h: every 4-byte SAD is sad4_acc, four Xpulp instructions) and its own search and
 * half-pixel steps (flow_search.c or flow_search_fast.c; half_<variant>.c). */
#include <pmsis.h>

#include "flow_kernel.h"
#include "flow_simd.h"

/* The steps' asm reads next through the context (c->next), so the kernel's `next` goes unused. */
#define PXFLOW_POI_CONTEXT flow_ctx
#define PXFLOW_POI_INTEGER_SEARCH(c, next, blk, x, y, bx, by) \
  ((void)(next), flow_integer_search(c, blk, x, y, bx, by))
#define PXFLOW_POI_HALF_SADS(c, next, blk, mx, my, sub) \
  ((void)(next), variant_half_sads(c, blk, mx, my, sub))
#ifdef PXFLOW_GAP8_FAST_HOOKS
#define PXFLOW_POI_ACCEPTED variant_accepted
#endif
#include "pxflow_spec/poi_kernel.h"

/* Fills the record of POI n; the master cleared it, so undefined fields stay 0. */
static void flow_poi(const flow_ctx *c, uint32_t n) {
  pxflow_poi_kernel(c, c->prev, c->next, c->poi_xy[2 * n], c->poi_xy[2 * n + 1], &c->records[n]);
}

void flow_team_entry(void *arg) {
  const flow_ctx *c = arg;
  const uint32_t core = (uint32_t)pi_core_id();
  variant_prepare(c, core);
  if (c->split == PXFLOW_GAP8_SPLIT_CHUNKED) {
    const uint32_t chunk = (c->pois + c->cores - 1) / c->cores;
    const uint32_t end = (core + 1) * chunk < c->pois ? (core + 1) * chunk : c->pois;
    for (uint32_t n = core * chunk; n < end; ++n) flow_poi(c, n);
  } else {
    for (uint32_t n = core; n < c->pois; n += c->cores) flow_poi(c, n);
  }
#ifdef PXFLOW_GAP8_FAST_HOOKS
  variant_finish(c, core);
#endif
}
