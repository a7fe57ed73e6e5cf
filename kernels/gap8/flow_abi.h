/* The contract between the GAP8 flow kernel (the C files of kernels/gap8, RISC-V) and its host
 * (hosts/gap8/, C++): the parameter block the host writes into L2 before the run, the per-pair
 * result block and record layout the kernel writes back to L2, and the L1 budget both sides
 * compute the same way. Plain C so that both compilers read the same definitions; the record, the
 * parameter block, the codes and the estimate are the spec core's (spec/README.md). */
#ifndef PXFLOW_GAP8_FLOW_ABI_H
#define PXFLOW_GAP8_FLOW_ABI_H

#include <stdint.h>

#include "pxflow_spec/spec.h"

#define PXFLOW_GAP8_MAGIC 0x70784738u /* "pxG8": the host really wrote the block */

/* Kernel exit status (main's return value) besides 0. */
#define PXFLOW_GAP8_BAD_PARAMS 10
#define PXFLOW_GAP8_NO_L1 11

/* How the POIs are split over the team: the paper's round robin by core id, or one contiguous
 * chunk per core. */
#define PXFLOW_GAP8_SPLIT_ROUND_ROBIN 0u
#define PXFLOW_GAP8_SPLIT_CHUNKED 1u

typedef struct {
  uint32_t magic;
  pxflow_param_block spec; /* SPEC §1 */
  uint32_t pairs;          /* frame pairs in this run */
  uint32_t cores;          /* team size of the flow phase, 1..8 */
  uint32_t split;          /* PXFLOW_GAP8_SPLIT_* */
  uint32_t frames_l2;      /* pair p: prev at frames_l2 + 2*p*W*H, next W*H bytes later */
  uint32_t records_l2;     /* pair p: its POI records at records_l2 + p*pois*32 */
  uint32_t results_l2;     /* pair p: pxflow_gap8_result at results_l2 + p*sizeof(result) */
} pxflow_gap8_params;

/* The kernel's own frame estimate (soft-float on core 0) and its cycle breakdown, per pair. */
typedef struct {
  pxflow_estimate estimate;
  uint32_t pois;
  uint32_t cycles_init;      /* grid and result clearing, while the DMA runs */
  uint32_t cycles_dma;       /* from the DMA start until both frames are in L1 */
  uint32_t cycles_flow;      /* fork .. join: the per-POI work of the team */
  uint32_t cycles_averaging; /* histograms and the float estimate on core 0 */
  uint32_t cycles_output;    /* records back to L2 */
  uint32_t cycles_total;
  uint32_t reserved;
} pxflow_gap8_result;

/* One frame (or half-pixel plane) in L1: W*H bytes plus one row and a word of slack, because the
 * word-wide interpolations read up to one row and three bytes past the cells they need (the
 * values computed from the slack are never used). */
static inline uint32_t pxflow_gap8_frame_l1_bytes(uint32_t w, uint32_t h) {
  return (w * h + w + 8u + 7u) & ~7u;
}

/* Everything the kernel takes from the L1 heap for one run: prev, next, `planes` full-frame
 * half-pixel planes (3 for the global variant, else 0), the POI coordinates and the records. */
static inline uint32_t pxflow_gap8_l1_bytes(uint32_t w, uint32_t h, uint32_t pois,
                                            uint32_t planes) {
  return (2u + planes) * pxflow_gap8_frame_l1_bytes(w, h) + ((pois * 4u + 7u) & ~7u) +
         pois * PXFLOW_RECORD_BYTES;
}

#endif
