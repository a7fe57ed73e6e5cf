/* The firmware's 4-byte primitives (SPEC §7) in plain C, so that any 32-bit core runs the shared
 * per-POI kernel (pxflow_spec/poi_kernel.h); a port with USAD8/USADA8/UHADD8 swaps these for its
 * intrinsics, as kernels/cortex-m4/m4_simd.h does. */
#ifndef PXDUT_PRIMITIVES_H
#define PXDUT_PRIMITIVES_H

#include <stdint.h>

/* Four pixels from any address, little-endian lanes (the lanes are independent: byte order
 * never changes a result). */
static inline uint32_t pxdut_load4(const uint8_t *p) {
  return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* USADA8: acc + sum over the four bytes of |a_i - b_i|. */
static inline uint32_t pxdut_usada8(uint32_t a, uint32_t b, uint32_t acc) {
  for (int lane = 0; lane < 32; lane += 8) {
    const int32_t d = (int32_t)((a >> lane) & 0xFFu) - (int32_t)((b >> lane) & 0xFFu);
    acc += (uint32_t)(d < 0 ? -d : d);
  }
  return acc;
}

/* UHADD8: per byte floor((a + b) / 2) with a 9-bit intermediate, carry-free (SPEC §7). */
static inline uint32_t pxdut_uhadd8(uint32_t a, uint32_t b) {
  return (a & b) + (((a ^ b) & 0xFEFEFEFEu) >> 1);
}

#define PXFLOW_POI_LD4(p) pxdut_load4(p)
#define PXFLOW_POI_SAD4_ACC(acc, a, b) pxdut_usada8(a, b, acc)
#define PXFLOW_POI_AVG4(a, b) pxdut_uhadd8(a, b)

#endif
