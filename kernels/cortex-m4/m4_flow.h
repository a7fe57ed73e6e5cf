/* The PX4FLOW kernel for the Cortex-M4 (SPEC §2-§4), in the firmware's shape: compute_diff,
 * compute_sad_8x8 and compute_subpixel of PX4/PX4-Flow src/modules/flow/flow.c, with the DSP
 * instructions USAD8, USADA8 and UHADD8 (m4_simd.h). Freestanding C99: no heap, no stdio. The
 * record, the parameter block, their limits and the grid are the spec core's (spec/README.md); the
 * frame estimate (SPEC §5) is dut/'s pxdut_estimate_flow, which every firmware links and
 * compiles with the same flags, so on the FPU (-mfloat-abi=hard -mfpu=fpv4-sp-d16,
 * -ffp-contract=off: every float operation rounds once, as the host's reference/estimate.cpp
 * does). */
#ifndef PXFLOW_M4_FLOW_H
#define PXFLOW_M4_FLOW_H

#include <stdint.h>

#include "pxflow_spec/spec.h"

/* The record of the POI whose block's top-left corner is (x, y). Every field is written (the
 * ones a status does not define and the padding as 0). prev and next are W x H, stride W. */
void m4_flow_poi(const pxflow_param_block *p, const uint8_t *prev, const uint8_t *next, uint32_t x,
                 uint32_t y, pxflow_poi_record *rec);

/* The records of every grid POI of one pair, in grid order (pxflow_poi_count of them). The
 * parameters must have passed pxflow_check_params. */
void m4_flow_frame(const pxflow_param_block *p, const uint8_t *prev, const uint8_t *next,
                   pxflow_poi_record *records);

#endif
