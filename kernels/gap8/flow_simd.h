/* The 4-byte vocabulary of the PX4FLOW firmware (SPEC §7) in Xpulp instructions. GAP8 has no
 * USAD8: one 4-byte SAD is four instructions (the paper's "4 cycles instead of 1"). */
#ifndef PXFLOW_GAP8_FLOW_SIMD_H
#define PXFLOW_GAP8_FLOW_SIMD_H

#include <stdint.h>

#include "xpulp.h"

/* Four bytes from any address: RI5CY splits a misaligned lw in two accesses by itself, as the
 * firmware's *(uint32_t *)&image[...] does on the Cortex-M4. GCC would emit four lbu for a
 * memcpy on this strict-alignment target, hence the one-instruction asm. */
static inline uint32_t ld4(const uint8_t *p) {
  uint32_t v;
  __asm__("lw %0, %1" : "=r"(v) : "m"(*(const uint32_t *)p));
  return v;
}

/* Four bytes to any address (the global planes' rows need not be word aligned). */
static inline void st4(uint8_t *p, uint32_t v) {
  __asm__("sw %1, %0" : "=m"(*(uint32_t *)p) : "r"(v));
}

/* acc + USAD8(a, b): |a - b| per byte as maxu - minu, then a dot product with ones. */
static inline uint32_t sad4_acc(uint32_t acc, uint32_t a, uint32_t b) {
  const uint32_t diff = gap8_pv_sub_b(gap8_pv_maxu_b(a, b), gap8_pv_minu_b(a, b));
  return gap8_pv_sdotup_sc_b(acc, diff, 1u);
}

/* UHADD8: per byte floor((a + b) / 2). pv.avgu.b is the floor average (never round up). */
static inline uint32_t avg4(uint32_t a, uint32_t b) { return gap8_pv_avgu_b(a, b); }

#endif
