/* An on-target unit test built from `pxflow vectors --format c`, run here on the host: the
 * portable kernel of dut/ on every pair of the vectors, its records and its own estimate checked
 * by the vectors' freestanding checker. Prints one line per failing pair; exit 1 on any. */
#include <stdio.h>

#include "pxdut.h"
#include "pxflow_vectors.h"

static pxdut_record records[PXV_POIS];

int main(void) {
  const pxdut_params p = {PXV_WIDTH, PXV_HEIGHT, PXV_S,  8u,           PXV_B,
                          PXV_FT,    PXV_VT,     PXV_HF, PXV_MINCOUNT, 0u};
  int failed = 0;
  for (uint32_t pair = 0; pair < PXV_PAIRS; ++pair) {
    const uint8_t *prev = pxv_frames + 2ul * pair * PXV_WIDTH * PXV_HEIGHT;
    pxdut_kernel_portable(&p, prev, prev + PXV_WIDTH * PXV_HEIGHT, records);
    uint8_t bytes[PXV_POIS * 32u];
    for (uint32_t n = 0; n < PXV_POIS; ++n) { /* SPEC 4's little-endian bytes */
      const pxdut_record *r = &records[n];
      uint8_t *b = bytes + 32u * n;
      const uint16_t h[] = {r->x, r->y};
      b[0] = (uint8_t)h[0], b[1] = (uint8_t)(h[0] >> 8), b[2] = (uint8_t)h[1];
      b[3] = (uint8_t)(h[1] >> 8), b[4] = r->status, b[5] = 0;
      b[6] = (uint8_t)r->feature, b[7] = (uint8_t)(r->feature >> 8);
      b[8] = (uint8_t)r->dx, b[9] = (uint8_t)r->dy;
      b[10] = (uint8_t)r->sad, b[11] = (uint8_t)(r->sad >> 8), b[12] = r->dir, b[13] = 0;
      for (int k = 0; k < 8; ++k)
        b[14 + 2 * k] = (uint8_t)r->sub[k], b[15 + 2 * k] = (uint8_t)(r->sub[k] >> 8);
      b[30] = (uint8_t)r->hx, b[31] = (uint8_t)r->hy;
    }
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
