/* SPEC §3 on the Cortex-M4: the shared per-POI kernel (pxflow_spec/poi_kernel.h, the firmware's
 * compute_diff, compute_sad_8x8 for every candidate and compute_subpixel: 12 UHADD8 and 8 USADA8
 * per group of 4 pixels, the values made on the spot, the "original" variant of SPEC §6) with its
 * portable steps and this core's primitives: every 4-byte SAD is one USADA8, every 4-pixel floor
 * average one UHADD8 (m4_simd.h). Coordinates and offsets are 32-bit (the firmware's uint16_t
 * offsets would wrap beyond 64 KiB frames). */
#include "m4_flow.h"
#include "m4_simd.h"

#define PXFLOW_POI_CONTEXT pxflow_param_block
#include "pxflow_spec/poi_kernel.h"

void m4_flow_poi(const pxflow_param_block *p, const uint8_t *prev, const uint8_t *next, uint32_t x,
                 uint32_t y, pxflow_poi_record *rec) {
  pxflow_poi_record r = {0}; /* SPEC §4: undefined fields and padding are 0 */
  pxflow_poi_kernel(p, prev, next, x, y, &r);
  *rec = r;
}
