/* An on-target unit test built from `pxflow vectors --format c`, run here on the host: the
 * portable kernel of dut/ on every pair of the vectors, its records and its own estimate checked
 * by the vectors' freestanding checker. Prints one line per failing pair; exit 1 on any. */
#include <stdio.h>

#include "pxdut.h"
#include "pxflow_vectors.h"

static pxdut_record records[PXV_POIS];

int main(void) {
  const pxdut_params p = {PXV_WIDTH, PXV_HEIGHT, PXV_S,  PXV_T,        PXV_B,
                          PXV_FT,    PXV_VT,     PXV_HF, PXV_MINCOUNT, PXV_GC};
  int failed = 0;
  for (uint32_t pair = 0; pair < PXV_PAIRS; ++pair) {
    const uint8_t *prev = pxv_frames + 2ul * pair * PXV_WIDTH * PXV_HEIGHT;
    pxdut_kernel_portable(&p, prev, prev + PXV_WIDTH * PXV_HEIGHT, records);
    uint8_t bytes[PXV_POIS * PXFLOW_RECORD_BYTES];
    for (uint32_t n = 0; n < PXV_POIS; ++n) /* SPEC 4's little-endian bytes */
      pxflow_record_to_bytes(&records[n], bytes + PXFLOW_RECORD_BYTES * n);
    pxdut_estimate est;
    pxdut_estimate_flow(records, PXV_POIS, &p, &est);
    union {
      float f;
      uint32_t u;
    } x, y;
    x.f = est.flow_x, y.f = est.flow_y;
    const long at = pxv_check_records(pair, bytes);
    if (at >= 0) printf("FAIL pair %u: record byte %ld differs\n", (unsigned)pair, at), ++failed;
    if (pxv_check_flow(pair, x.u, y.u, est.quality))
      printf("FAIL pair %u: flow differs\n", (unsigned)pair), ++failed;
  }
  printf("%u pairs, %d failed\n", (unsigned)PXV_PAIRS, failed);
  return failed ? 1 : 0;
}
