/* The GAP8 flow kernel's master (cluster core 0), per frame pair: start the DMA of both frames
 * into L1, compute the POI grid and clear the records while it runs, wait, fork the team over
 * the POIs, then build the histograms and the float estimate, and send everything back to L2.
 * The host writes pxflow_params before the run (docs/gap8-kernel.md). */
#include <pmsis.h>

#include "flow_kernel.h"

/* In .data, not .bss: the start-up code clears .bss after the host has written it. */
volatile pxflow_gap8_params pxflow_params __attribute__((section(".data"))) = {0};

static uint32_t cycles_now(void) { return pi_perf_read(PI_PERF_CYCLES); }

/* Writes the x, y pairs of every POI in record order (y outer, x inner): SPEC §2's grid. */
static void build_grid(const pxflow_param_block *p, uint16_t *xy) {
  const pxflow_grid_axis ax = pxflow_grid_axis_of(p->width, p->search_radius, p->blocks);
  const pxflow_grid_axis ay = pxflow_grid_axis_of(p->height, p->search_radius, p->blocks);
  for (uint32_t j = 0, y = ay.first; j < ay.count; ++j, y += ay.step) {
    for (uint32_t i = 0, x = ax.first; i < ax.count; ++i, x += ax.step) {
      *xy++ = (uint16_t)x;
      *xy++ = (uint16_t)y;
    }
  }
}

/* Weak: the fast variant's does nothing, its team clears the records (flow_kernel.h). */
__attribute__((weak)) void flow_clear_words(void *dst, uint32_t bytes) {
  uint32_t *w = dst;
  for (uint32_t n = 0; n < bytes / 4; ++n) w[n] = 0;
}

/* Weak (a hook of the past: the fast variant now brings its whole estimate, flow_kernel.h). */
__attribute__((weak)) float flow_window_mean(const uint16_t *hist, int lo, int hi) {
  return pxflow_window_mean_float(hist, lo, hi);
}

#ifndef PXFLOW_GAP8_FAST_HOOKS
/* SPEC §5 on core 0 after the join (the spec core's estimate). The cores have no FPU: every float
 * operation is a libgcc soft-float call, correctly rounded, so the bits match the host's
 * estimate_flow (both built with -ffp-contract=off). Not inlined: its cycles are the
 * "averaging" phase, one call as before. */
static __attribute__((noinline)) void flow_estimate(const pxflow_poi_record *records, uint32_t pois,
                                                    const pxflow_gap8_params *p,
                                                    pxflow_gap8_result *out) {
  pxflow_estimate_flow(records, pois, &p->spec, flow_window_mean, &out->estimate);
}
#endif

static void run_pair(const pxflow_gap8_params *p, flow_ctx *c, uint32_t pair) {
  const uint32_t frame = p->spec.width * p->spec.height;
  const uint32_t rec_bytes = c->pois * PXFLOW_RECORD_BYTES;
  pxflow_gap8_result r = {0};
  const uint32_t t0 = cycles_now();
  pi_cl_dma_cmd_t prev_cmd, next_cmd, out_cmd;
  const uint32_t src = p->frames_l2 + 2 * pair * frame;
  pi_cl_dma_cmd(src, (uint32_t)c->prev, frame, PI_CL_DMA_DIR_EXT2LOC, &prev_cmd);
  pi_cl_dma_cmd(src + frame, (uint32_t)c->next, frame, PI_CL_DMA_DIR_EXT2LOC, &next_cmd);
  build_grid(&p->spec, (uint16_t *)c->poi_xy);
  flow_clear_words(c->records, rec_bytes);
  const uint32_t t1 = cycles_now();
  pi_cl_dma_cmd_wait(&prev_cmd);
  pi_cl_dma_cmd_wait(&next_cmd);
  const uint32_t t2 = cycles_now();
  pi_cl_team_fork((int)c->cores, flow_team_entry, c);
  const uint32_t t3 = cycles_now();
  flow_estimate(c->records, c->pois, p, &r);
  const uint32_t t4 = cycles_now();
  pi_cl_dma_cmd(p->records_l2 + pair * rec_bytes, (uint32_t)c->records, rec_bytes,
                PI_CL_DMA_DIR_LOC2EXT, &out_cmd);
  pi_cl_dma_cmd_wait(&out_cmd);
  const uint32_t t5 = cycles_now();
  r.pois = c->pois;
  r.cycles_init = t1 - t0;
  r.cycles_dma = t2 - t0;
  r.cycles_flow = t3 - t2;
  r.cycles_averaging = t4 - t3;
  r.cycles_output = t5 - t4;
  r.cycles_total = t5 - t0;
  ((pxflow_gap8_result *)p->results_l2)[pair] = r;
}

static int valid(const pxflow_gap8_params *p) {
  /* GC may be on: the estimate has no body rates here, and with none the host's is the same. */
  return p->magic == PXFLOW_GAP8_MAGIC && p->cores >= 1 && p->cores <= 8 &&
         pxflow_check_params(&p->spec) == PXFLOW_PARAMS_OK;
}

int main(void) {
  const pxflow_gap8_params p = pxflow_params;
  if (!valid(&p)) return PXFLOW_GAP8_BAD_PARAMS;
  flow_ctx c = {0};
  c.width = p.spec.width;
  c.height = p.spec.height;
  c.search_radius = p.spec.search_radius;
  c.feature_threshold = p.spec.feature_threshold;
  c.sad_threshold = p.spec.sad_threshold;
  c.cores = p.cores;
  c.split = p.split;
  c.pois = pxflow_poi_count(&p.spec);
  const uint32_t frame = pxflow_gap8_frame_l1_bytes(c.width, c.height);
  uint8_t *l1 = pi_cl_l1_malloc(0, pxflow_gap8_l1_bytes(c.width, c.height, c.pois, variant_planes));
  if (!l1) return PXFLOW_GAP8_NO_L1;
  c.prev = l1;
  c.next = l1 + frame;
  for (uint32_t k = 0; k < variant_planes; ++k) c.planes[k] = l1 + (2 + k) * frame;
  c.poi_xy = (const uint16_t *)(l1 + (2 + variant_planes) * frame);
  c.records = (pxflow_poi_record *)((uint8_t *)c.poi_xy + ((c.pois * 4 + 7) & ~7u));
  pi_perf_conf(1u << PI_PERF_CYCLES);
  pi_perf_reset();
  pi_perf_start();
  for (uint32_t pair = 0; pair < p.pairs; ++pair) run_pair(&p, &c, pair);
  pi_perf_stop();
  return 0;
}
