/* The PX4FLOW kernel for the Cortex-M4 (SPEC §2-§4), in the firmware's shape: compute_diff,
 * compute_sad_8x8 and compute_subpixel of PX4/PX4-Flow src/modules/flow/flow.c, with the DSP
 * instructions USAD8, USADA8 and UHADD8 (m4_simd.h). Freestanding C99: no heap, no stdio. The
 * frame estimate (SPEC §5) is dut/'s pxdut_estimate_flow, which every firmware links and
 * compiles with the same flags, so on the FPU (-mfloat-abi=hard -mfpu=fpv4-sp-d16,
 * -ffp-contract=off: every float operation rounds once, as the host's reference/estimate.cpp
 * does). */
#ifndef PXFLOW_M4_FLOW_H
#define PXFLOW_M4_FLOW_H

#include <stdint.h>

#define M4_FLOW_TILE 8u        /* T: the kernel's 8x8 block */
#define M4_FLOW_MAX_RADIUS 31u /* S: a half-pixel displacement fits an i8 */

/* SPEC §1's parameters (T is always 8 and not a field). */
typedef struct {
  uint32_t width, height;                    /* W, H; row stride = W */
  uint32_t search_radius;                    /* S, 1..31 */
  uint32_t blocks;                           /* B, grid points per axis (upper bound), 1..255 */
  uint32_t feature_threshold, sad_threshold; /* FT, VT */
  uint32_t hist_filter;                      /* HF: 0 or 1 */
  uint32_t min_count;                        /* MINCOUNT */
} m4_flow_params;

/* SPEC §4's record: 32 bytes, the layout of reference/record.hpp's PoiRecord. */
typedef struct {
  uint16_t x, y;
  uint8_t status, pad0;
  uint16_t feature;
  int8_t dx, dy;
  uint16_t sad;
  uint8_t dir, pad1;
  uint16_t sub[8];
  int8_t hx, hy;
} m4_flow_record;

typedef char m4_flow_record_is_32_bytes[sizeof(m4_flow_record) == 32 ? 1 : -1];

#define M4_FLOW_DROPPED 0u  /* feature < FT */
#define M4_FLOW_REJECTED 1u /* best integer SAD >= VT */
#define M4_FLOW_ACCEPTED 2u
#define M4_FLOW_DIR_NONE 8u /* the integer match won the half-pixel vote */

/* Why a parameter block cannot run (m4_flow_check). */
typedef enum {
  M4_FLOW_OK = 0,
  M4_FLOW_BAD_RADIUS,    /* S outside 1..31 */
  M4_FLOW_BAD_BLOCKS,    /* B outside 1..255 */
  M4_FLOW_BAD_THRESHOLD, /* FT or VT outside u16, HF not 0/1 */
  M4_FLOW_NO_POI,        /* a frame too small for one POI */
  M4_FLOW_TOO_LARGE,     /* W or H beyond 16384 (records store u16 coordinates) */
} m4_flow_status;

m4_flow_status m4_flow_check(const m4_flow_params *p);

/* POIs along one axis of `side` pixels (SPEC §2), and the first coordinate and step. */
uint32_t m4_flow_axis(uint32_t side, const m4_flow_params *p, uint32_t *first, uint32_t *step);

/* Number of grid POIs of a frame: the records one pair produces. */
uint32_t m4_flow_poi_count(const m4_flow_params *p);

/* The record of the POI whose block's top-left corner is (x, y). Every field is written (the
 * ones a status does not define and the padding as 0). prev and next are W x H, stride W. */
void m4_flow_poi(const m4_flow_params *p, const uint8_t *prev, const uint8_t *next, uint32_t x,
                 uint32_t y, m4_flow_record *rec);

/* The records of every grid POI of one pair, in grid order (m4_flow_poi_count of them). The
 * parameters must have passed m4_flow_check. */
void m4_flow_frame(const m4_flow_params *p, const uint8_t *prev, const uint8_t *next,
                   m4_flow_record *records);

#endif
