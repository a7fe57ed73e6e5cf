/* The fast variant's parts around the POIs (beyond the paper): the records cleared by the team,
 * not by core 0 (flow_main.c's weak flow_clear_words replaced by nothing), and SPEC §5's estimate
 * in integers, by the team at the end of the fork (the hooks of flow_kernel.h). */
#define PXFLOW_GAP8_FAST_HOOKS 1
#include "fast_float.h"
#include "fast_tables.h"
#include "flow_kernel.h"

/* The records are cleared by the team (fast_team_begin), not by core 0 while the DMA runs. */
void flow_clear_words(void *dst, uint32_t bytes) { (void)dst, (void)bytes; }

/* SPEC §5 in integers (fast_float.h), the same bits as the spec core's soft-float estimate
 * (pxflow_estimate_flow), which the host compares on every run; by the team, inside the fork:
 * each core counts its accepted POIs into its row of g_hist as it finishes them
 * (variant_accepted); at the end (variant_finish) a barrier, the cores add the rows up bin by
 * bin (bins round robin), a barrier, then core a (a = 0 for x, 1 for y; a single core takes
 * both) computes its axis. The sums are the same whatever the split. A row's word b holds bin b
 * of x in its low half and of y in its high half: a bin counts at most the POIs (< 2048,
 * fast_float.h), so the halves never carry into each other and one 32-bit add sums both axes. */
extern volatile pxflow_gap8_params pxflow_params; /* flow_main.c */

/* Core k's counts: its histogram row, its accepted POIs and the sums of their hx and hy. */
typedef struct {
  uint32_t bin[PXFLOW_MAX_BINS];
  int32_t count, sum[2];
} estimate_row;

typedef struct {
  estimate_row row[8];                  /* per core; rows of absent cores stay 0 */
  uint32_t merged[PXFLOW_MAX_BINS + 4]; /* bin b at b + 2, the cores' rows added up; 2 bins of 0
                                           on each side, never written */
  uint32_t bits[2];                     /* flow_x, flow_y as float bits */
  int32_t count;                        /* accepted POIs, all cores */
} estimate_team;

PI_L1 estimate_team g_estimate = {{{{0}, 0, {0}}}, {0}, {0}, 0};

void fast_team_begin(const flow_ctx *c, uint32_t core) {
  for (uint32_t n = core; n < c->pois; n += c->cores) { /* the 8 words of each record */
    uint32_t *r = (uint32_t *)&c->records[n];
    r[0] = r[1] = r[2] = r[3] = r[4] = r[5] = r[6] = r[7] = 0;
  }
  estimate_row *row = &g_estimate.row[core];
  for (uint32_t b = 0; b < pxflow_hist_bins(c->search_radius); ++b) row->bin[b] = 0;
  row->count = row->sum[0] = row->sum[1] = 0;
}

void variant_accepted(const flow_ctx *c, const pxflow_poi_record *rec) {
  estimate_row *row = &g_estimate.row[pi_core_id()];
  const uint32_t zero = 2 * c->search_radius + 1;
  row->bin[rec->hx + zero] += 1;
  row->bin[rec->hy + zero] += 1u << 16;
  row->count += 1;
  row->sum[0] += rec->hx;
  row->sum[1] += rec->hy;
}

/* Axis a's flow as float bits (count > MINCOUNT). */
static uint32_t axis_bits(uint32_t hist_filter, uint32_t s, uint32_t cores, uint32_t a,
                          uint32_t count) {
  const uint32_t nbins = pxflow_hist_bins(s), shift = 16 * a;
  if (!hist_filter) {
    int32_t sum = 0;
    for (uint32_t k = 0; k < cores; ++k) sum += g_estimate.row[k].sum[a];
    return fast_mean_bits(sum, count);
  }
  const uint32_t *m = g_estimate.merged + 2; /* m[-2], m[-1], m[nbins], m[nbins + 1] are 0 */
  uint32_t peak = 0, top = m[0] >> shift & 0xFFFFu;
  for (uint32_t b = 1; b < nbins; ++b) {
    const uint32_t h = m[b] >> shift & 0xFFFFu;
    if (h > top) peak = b, top = h; /* strict: the first maximum wins */
  }
  /* SPEC's window, bins max(p - 2, 0) .. min(p + 2, nbins - 1): the bins beyond the histogram
   * are 0 here, so p - 2 .. p + 2 gives the same sums (b < 0 only where h = 0). */
  uint32_t value = 0, weight = 0; /* the spec's float sums, exact: these integers */
  for (int32_t b = (int32_t)peak - 2; b <= (int32_t)peak + 2; ++b) {
    const uint32_t h = m[b] >> shift & 0xFFFFu;
    value += (uint32_t)b * h;
    weight += h;
  }
  return fast_filtered_bits(value, weight, 2 * s + 1);
}

void variant_finish(const flow_ctx *c, uint32_t core) {
  const uint32_t cores = c->cores, s = c->search_radius;
  team_sync(); /* every POI counted */
  for (uint32_t b = core; b < pxflow_hist_bins(s); b += cores) {
    uint32_t both = 0;
    for (uint32_t k = 0; k < cores; ++k) both += g_estimate.row[k].bin[b];
    g_estimate.merged[b + 2] = both;
  }
  team_sync();
  if (core >= 2) return;
  int32_t count = 0;
  for (uint32_t k = 0; k < cores; ++k) count += g_estimate.row[k].count;
  if (core == 0) g_estimate.count = count;
  const uint32_t min_count = pxflow_params.spec.min_count; /* in L2 */
  const uint32_t hist_filter = pxflow_params.spec.hist_filter;
  /* core 0: x, core 1: y; a single core: both */
  for (uint32_t a = core; a < 2; a += cores)
    g_estimate.bits[a] =
        count > (int32_t)min_count ? axis_bits(hist_filter, s, cores, a, (uint32_t)count) : 0;
}

void flow_estimate(const pxflow_poi_record *records, uint32_t pois, const pxflow_gap8_params *p,
                   pxflow_gap8_result *out) {
  (void)records, (void)pois; /* the team has counted them (variant_accepted) */
  const int32_t count = g_estimate.count;
  out->estimate.meancount = count;
  out->estimate.quality = 0;
  if (count > (int32_t)p->spec.min_count)
    out->estimate.quality = count * 255 / (int32_t)(p->spec.blocks * p->spec.blocks);
  /* the bits as floats (0, +0.0f, at or below MINCOUNT): no float arithmetic */
  const union {
    uint32_t u[2];
    float f[2];
  } flow = {{g_estimate.bits[0], g_estimate.bits[1]}};
  out->estimate.flow_x = flow.f[0];
  out->estimate.flow_y = flow.f[1];
}
