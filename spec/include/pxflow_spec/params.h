/* SPEC §1's parameter block and every limit on it: the one definition the freestanding kernels
 * (dut/'s engine and portable kernel, kernels/cortex-m4, kernels/gap8) take, and the values
 * reference/params.cpp static_asserts its readable C++ limits against. Where SPEC is silent the
 * choice is docs/spec-notes.md's. */
#ifndef PXFLOW_SPEC_PARAMS_H
#define PXFLOW_SPEC_PARAMS_H

#include <stdint.h>

/* The parameter block: SPEC §1's values, one u32 each, in the order of the device protocol's
 * PARAMS body (docs/dut-protocol.md). */
typedef struct {
  uint32_t width, height;                    /* W, H: pixels, row stride = W */
  uint32_t search_radius;                    /* S */
  uint32_t tile;                             /* T, always PXFLOW_TILE */
  uint32_t blocks;                           /* B, grid points per axis (upper bound) */
  uint32_t feature_threshold, sad_threshold; /* FT, VT */
  uint32_t hist_filter;                      /* HF, 0 or 1 */
  uint32_t min_count;                        /* MINCOUNT */
  uint32_t gyro_comp;                        /* GC, 0 or 1 */
} pxflow_param_block;

#define PXFLOW_PARAM_FIELDS 10u

/* T: the kernel's 8x8 block; the record layout and the 4-byte packing assume it. */
#define PXFLOW_TILE 8u
/* S: 1..31, so that a half-pixel displacement 2S+1 fits an i8 (SPEC §1). */
#define PXFLOW_MIN_RADIUS 1u
#define PXFLOW_MAX_RADIUS 31u
/* B: at least 1 (the grid step divides by B); at most 255, so that B*B POIs fit the u16
 * histogram bins and the quality formula stays <= 255. */
#define PXFLOW_MIN_BLOCKS 1u
#define PXFLOW_MAX_BLOCKS 255u
/* FT, VT and MINCOUNT: the u16 range of the values they are compared with. */
#define PXFLOW_MAX_THRESHOLD 65535u
/* W and H: records store u16 coordinates, and a larger frame would be a typo (docs/spec-notes.md);
 * W*H at most 2^26 pixels (64 Mpx). */
#define PXFLOW_MAX_FRAME_SIDE 16384u
#define PXFLOW_MAX_FRAME_PIXELS 67108864u
/* Histogram bins of SPEC §5: 2*(2S+1)+1, at most this many (S = 31). */
#define PXFLOW_MAX_BINS (2u * (2u * PXFLOW_MAX_RADIUS + 1u) + 1u)
/* The integer search's starting "best" (SPEC §3 step 2). */
#define PXFLOW_SAD_SENTINEL 0xFFFFFFFFu

static inline uint32_t pxflow_hist_bins(uint32_t search_radius) {
  return 2u * (2u * search_radius + 1u) + 1u;
}

/* The smallest side with one POI: lo < hi on the axis, lo = S+1, hi = side-(S+1)-T (SPEC §2). */
static inline uint32_t pxflow_min_frame_side(uint32_t search_radius) {
  return 2u * (search_radius + 1u) + PXFLOW_TILE + 1u;
}

/* Why a parameter block cannot run, in the order pxflow_check_params tests. */
typedef enum {
  PXFLOW_PARAMS_OK = 0,
  PXFLOW_PARAMS_BAD_TILE,      /* T != 8 */
  PXFLOW_PARAMS_BAD_RADIUS,    /* S outside 1..31 */
  PXFLOW_PARAMS_BAD_BLOCKS,    /* B outside 1..255 */
  PXFLOW_PARAMS_BAD_THRESHOLD, /* FT, VT or MINCOUNT beyond u16 */
  PXFLOW_PARAMS_BAD_FLAG,      /* HF or GC not 0 or 1 */
  PXFLOW_PARAMS_TOO_LARGE,     /* W or H beyond PXFLOW_MAX_FRAME_SIDE, or W*H beyond the pixels */
  PXFLOW_PARAMS_NO_POI         /* a side too small for one POI */
} pxflow_params_problem;

/* SPEC §1's validation: the first problem of the block, or PXFLOW_PARAMS_OK. */
static inline pxflow_params_problem pxflow_check_params(const pxflow_param_block *p) {
  if (p->tile != PXFLOW_TILE) return PXFLOW_PARAMS_BAD_TILE;
  if (p->search_radius < PXFLOW_MIN_RADIUS || p->search_radius > PXFLOW_MAX_RADIUS)
    return PXFLOW_PARAMS_BAD_RADIUS;
  if (p->blocks < PXFLOW_MIN_BLOCKS || p->blocks > PXFLOW_MAX_BLOCKS)
    return PXFLOW_PARAMS_BAD_BLOCKS;
  if (p->feature_threshold > PXFLOW_MAX_THRESHOLD || p->sad_threshold > PXFLOW_MAX_THRESHOLD ||
      p->min_count > PXFLOW_MAX_THRESHOLD)
    return PXFLOW_PARAMS_BAD_THRESHOLD;
  if (p->hist_filter > 1u || p->gyro_comp > 1u) return PXFLOW_PARAMS_BAD_FLAG;
  if (p->width > PXFLOW_MAX_FRAME_SIDE || p->height > PXFLOW_MAX_FRAME_SIDE ||
      p->width * p->height > PXFLOW_MAX_FRAME_PIXELS) /* no wrap: both sides <= 2^14 */
    return PXFLOW_PARAMS_TOO_LARGE;
  const uint32_t min_side = pxflow_min_frame_side(p->search_radius);
  if (p->width < min_side || p->height < min_side) return PXFLOW_PARAMS_NO_POI;
  return PXFLOW_PARAMS_OK;
}

/* One line for a device's error reply or a self-test's failure (the limits are above). */
static inline const char *pxflow_params_problem_text(pxflow_params_problem problem) {
  switch (problem) {
    case PXFLOW_PARAMS_OK:
      return "the parameters are valid";
    case PXFLOW_PARAMS_BAD_TILE:
      return "T is not the kernel's tile";
    case PXFLOW_PARAMS_BAD_RADIUS:
      return "S is out of range";
    case PXFLOW_PARAMS_BAD_BLOCKS:
      return "B is out of range";
    case PXFLOW_PARAMS_BAD_THRESHOLD:
      return "FT, VT or MINCOUNT is beyond u16";
    case PXFLOW_PARAMS_BAD_FLAG:
      return "HF or GC is neither 0 nor 1";
    case PXFLOW_PARAMS_TOO_LARGE:
      return "the frame is beyond the largest side or pixel count";
    case PXFLOW_PARAMS_NO_POI:
      return "the grid does not fit the frame";
  }
  return "unknown problem";
}

#endif
