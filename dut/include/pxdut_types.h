/* The types shared by the engine, the hooks and the kernel (the spec core's, spec/README.md),
 * plus the compile-time sizes of the engine's static buffers. */
#ifndef PXDUT_TYPES_H
#define PXDUT_TYPES_H

#include <stdint.h>

#include "pxflow_spec/spec.h"

/* Sizes of the static buffers (override with -D at build time). The defaults take one 64x64
 * pair with the px4flow-64 grid (64 POIs) in 256-byte packets: about 11.5 KiB of RAM. */
#ifndef PXDUT_MAX_PIXELS
#define PXDUT_MAX_PIXELS 4096u /* per frame: W*H */
#endif
#ifndef PXDUT_MAX_POIS
#define PXDUT_MAX_POIS 64u
#endif
#ifndef PXDUT_MAX_PACKET
#define PXDUT_MAX_PACKET 256u /* decoded bytes from type to CRC; at least 64 */
#endif

/* SPEC §1's parameter block, SPEC §4's 32-byte record and SPEC §5's estimate are the spec
 * core's (spec/include/pxflow_spec); these names are the porting layer's, stable since protocol
 * version 1. */
typedef pxflow_param_block pxdut_params;
typedef pxflow_poi_record pxdut_record;
typedef pxflow_estimate pxdut_estimate;

#endif
