/* The types shared by the engine, the hooks and the kernel: SPEC §1's parameters and SPEC §4's
 * 32-byte record, plus the compile-time sizes of the engine's static buffers. */
#ifndef PXDUT_TYPES_H
#define PXDUT_TYPES_H

#include <stdint.h>

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

typedef struct {
  uint32_t width, height;                    /* W, H: pixels, row stride = W */
  uint32_t search_radius;                    /* S, 1..31 */
  uint32_t tile;                             /* T, always 8 */
  uint32_t blocks;                           /* B, grid points per axis (upper bound) */
  uint32_t feature_threshold, sad_threshold; /* FT, VT */
  uint32_t hist_filter;                      /* HF, 0 or 1 */
  uint32_t min_count;                        /* MINCOUNT */
  uint32_t gyro_comp;                        /* GC: always 0 in protocol version 1 */
} pxdut_params;

/* SPEC §4, the same field order and offsets as pxflow's PoiRecord (32 bytes). The engine writes
 * it to the wire field by field, little-endian. */
typedef struct {
  uint16_t x, y;
  uint8_t status, pad0; /* 0 dropped, 1 rejected, 2 accepted; pad0 = 0 */
  uint16_t feature;
  int8_t dx, dy;
  uint16_t sad;
  uint8_t dir, pad1; /* 0..8; pad1 = 0 */
  uint16_t sub[8];
  int8_t hx, hy;
} pxdut_record;

/* The frame estimate of SPEC §5 (no gyro compensation). */
typedef struct {
  float flow_x, flow_y;
  int32_t quality, meancount;
} pxdut_estimate;

#endif
