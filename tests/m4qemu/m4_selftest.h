/* The semihosted self-test firmware of the Cortex-M4 kernel (runs under qemu-system-arm -M
 * mps2-an386, prints through semihosting, exits with the number of failures). */
#ifndef PXFLOW_M4_SELFTEST_H
#define PXFLOW_M4_SELFTEST_H

#include <stdint.h>

#include "m4_flow.h"

/* One generated case (m4_vectors.h, written by m4_vectors_gen.cpp from the host reference). */
typedef struct {
  const char *name;
  pxflow_param_block params;
  uint32_t pixels;  /* offset of prev in m4_vec_pixels; next follows it */
  uint32_t records; /* index of its first record in m4_vec_records (32 bytes each) */
  uint32_t pois;
  uint32_t flow_x_bits, flow_y_bits;
  int32_t quality, meancount;
} m4_vec_case;

/* The DSP instructions against values worked out from the Arm ARM's pseudocode
 * (m4_selftest_simd.c); returns the number of failed checks, printing one line each. */
int m4_selftest_simd(void);

#endif
