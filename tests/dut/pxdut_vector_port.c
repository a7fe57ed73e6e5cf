/* pxdut-vector-port: a device that searches like a vector port (docs/check-corpus.md, "Every row
 * at its own edges"), with the bugs real vector ports have, for the test that the corpus catches
 * each at every vector length. `pxdut-vector-port LANES row|flat BUG`:
 *   LANES  candidates per vector (8, 16, 32 u16 lanes of 128, 256, 512 bits; 128 at 2048 bits)
 *   row    each row of the window (2S+1 candidates dx) searched in chunks of LANES; flat: the
 *          whole window, (2S+1)^2 candidates in raster order, in chunks (an SVE port's svcnth())
 *   BUG    none; chunk-base: a chunk's candidates indexed without the chunk's base (every chunk
 *          searches the first one's candidates); tail-over / tail-under: the last chunk's mask one
 *          lane too long / too short; half-lanes: the half-pixel directions 3 and 5 in each
 *          other's lanes.
 * Records come from the portable kernel (dut/src/pxdut_kernel.c); the integer search is then
 * redone the vector port's way and, where it finds another best, the record says what the port
 * would have found: a correct port (BUG none) answers bit for bit. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pxdut.h"
#include "ref_link.h"

typedef enum { kNone, kChunkBase, kTailOver, kTailUnder, kHalfLanes } bug_kind;

static const char *const kBugs[] = {"none", "chunk-base", "tail-over", "tail-under", "half-lanes"};
static uint32_t lanes = 8;
static int flat = 0;
static bug_kind bug = kNone;

int pxdut_port_read(uint8_t *buf, int max) { return ref_link_read(buf, max); }
int pxdut_port_write(const uint8_t *buf, int len) { return ref_link_write(buf, len); }
uint32_t pxdut_port_cycles(void) { return ref_link_nanoseconds(); }
uint32_t pxdut_port_cycles_hz(void) { return 1000000000u; }

static uint32_t block_sad(const uint8_t *blk, const uint8_t *cand, uint32_t w) {
  uint32_t acc = 0;
  for (uint32_t r = 0; r < 8; ++r)
    for (uint32_t c = 0; c < 8; ++c) {
      const int d = (int)blk[r * w + c] - (int)cand[r * w + c];
      acc += (uint32_t)(d < 0 ? -d : d);
    }
  return acc;
}

/* The integer search of SPEC §3 step 2 in chunks of `lanes` candidates: a chunk's lanes reduce to
 * their first minimum, which replaces the best only when strictly smaller (raster order kept). */
static void vector_search(const pxdut_params *p, const uint8_t *prev, const uint8_t *next,
                          uint32_t x, uint32_t y, uint32_t *best, int32_t *bx, int32_t *by) {
  const uint32_t w = p->width;
  const int32_t s = (int32_t)p->search_radius, n = 2 * s + 1;
  const int32_t total = flat ? n * n : n, rows = flat ? 1 : n;
  const int32_t last = total + (bug == kTailOver) - (bug == kTailUnder);
  *best = PXFLOW_SAD_SENTINEL;
  *bx = *by = 0;
  for (int32_t row = 0; row < rows; ++row)
    for (int32_t base = 0; base < total; base += (int32_t)lanes) {
      uint32_t chunk_best = PXFLOW_SAD_SENTINEL;
      int32_t cx = 0, cy = 0;
      for (int32_t lane = 0; lane < (int32_t)lanes; ++lane) {
        if (base + lane >= last) break; /* the tail mask */
        const int32_t at = (bug == kChunkBase ? 0 : base) + lane;
        const int32_t dx = -s + (flat ? at % n : at), dy = -s + (flat ? at / n : row);
        const uint32_t sad =
            block_sad(prev + y * w + x,
                      next + (uint32_t)((int32_t)y + dy) * w + (uint32_t)((int32_t)x + dx), w);
        if (sad < chunk_best) {
          chunk_best = sad;
          cx = dx;
          cy = dy;
        }
      }
      if (chunk_best < *best) {
        *best = chunk_best;
        *bx = cx;
        *by = cy;
      }
    }
}

static const int8_t kStepX[PXFLOW_DIRECTIONS + 1] = PXFLOW_STEP_X_TABLE;
static const int8_t kStepY[PXFLOW_DIRECTIONS + 1] = PXFLOW_STEP_Y_TABLE;

void pxdut_port_kernel(const pxdut_params *p, const uint8_t *prev, const uint8_t *next,
                       pxdut_record *out) {
  pxdut_kernel_portable(p, prev, next, out);
  const uint32_t pois = pxdut_poi_count(p);
  for (uint32_t i = 0; i < pois; ++i) {
    pxdut_record *rec = &out[i];
    if (rec->feature < p->feature_threshold) continue; /* dropped before the search */
    uint32_t best;
    int32_t bx, by;
    vector_search(p, prev, next, rec->x, rec->y, &best, &bx, &by);
    if (best != rec->sad || bx != rec->dx || by != rec->dy) { /* what the port reports */
      rec->dx = (int8_t)bx;
      rec->dy = (int8_t)by;
      rec->sad = (uint16_t)best;
      rec->status = best < p->sad_threshold ? PXFLOW_STATUS_ACCEPTED : PXFLOW_STATUS_REJECTED;
    }
    if (bug == kHalfLanes && rec->status == PXFLOW_STATUS_ACCEPTED) {
      const uint16_t t = rec->sub[3];
      rec->sub[3] = rec->sub[5];
      rec->sub[5] = t;
      uint32_t b = rec->sad;
      int dir = PXFLOW_DIR_NONE;
      for (int k = 0; k < 8; ++k)
        if (rec->sub[k] < b) {
          b = rec->sub[k];
          dir = k;
        }
      rec->dir = (uint8_t)dir;
      rec->hx = (int8_t)(2 * rec->dx + kStepX[dir]);
      rec->hy = (int8_t)(2 * rec->dy + kStepY[dir]);
    }
  }
}

int main(int argc, char **argv) {
  argc = ref_link_open(argc, argv);
  if (argc < 0) return 2;
  int known = -1;
  for (int b = 0; argc == 4 && b < 5; ++b)
    if (strcmp(argv[3], kBugs[b]) == 0) known = b;
  const long l = argc == 4 ? strtol(argv[1], NULL, 10) : 0;
  if (argc != 4 || l < 1 || l > 4096 || (strcmp(argv[2], "row") && strcmp(argv[2], "flat")) ||
      known < 0) {
    fprintf(stderr,
            "usage: pxdut-vector-port LANES row|flat none|chunk-base|tail-over|tail-under|"
            "half-lanes [--tcp PORT | --pty]\n");
    return 2;
  }
  lanes = (uint32_t)l;
  flat = strcmp(argv[2], "flat") == 0;
  bug = (bug_kind)known;
  static char name[96];
  snprintf(name, sizeof name, "vector-port %u lanes %s %s", lanes, argv[2], argv[3]);
  const pxdut_device dev = {name, PXDUT_BUILD_ID, "dut-ref-monotonic-ns"};
  pxdut_serve(&dev);
  return 0;
}
