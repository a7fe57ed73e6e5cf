/* The self-test firmware: the DSP semantics (m4_selftest_simd.c), then every generated case
 * (m4_vectors.h): the kernel's records against the host reference's, byte for byte, and the
 * estimate computed here on the FPU against the host's float bits. One line per failure, a
 * summary, and the number of failures as QEMU's exit status (semihosting). */
#include <stdio.h>
#include <string.h>

#include "board.h"
#include "m4_flow.h"
#include "m4_selftest.h"
#include "m4_vectors.h"

extern void initialise_monitor_handles(void); /* newlib's rdimon: semihosted stdio */

#define MAX_POIS 1024u
static m4_flow_record records[MAX_POIS];

static uint32_t float_bits(float f) {
  uint32_t u;
  memcpy(&u, &f, 4);
  return u;
}

static int check_case(const m4_vec_case *c) {
  const uint8_t *prev = m4_vec_pixels + c->pixels;
  const uint8_t *next = prev + c->params.width * c->params.height;
  if (m4_flow_check(&c->params) != M4_FLOW_OK || m4_flow_poi_count(&c->params) != c->pois ||
      c->pois > MAX_POIS) {
    printf("FAIL %s: parameters or POI count disagree with the host\n", c->name);
    return 1;
  }
  memset(records, 0xA5, sizeof records); /* a sentinel: an unwritten byte shows */
  m4_flow_frame(&c->params, prev, next, records);
  const uint8_t *want = m4_vec_records + 32u * c->records;
  for (uint32_t n = 0; n < c->pois; ++n) {
    const uint8_t *got = (const uint8_t *)&records[n];
    for (uint32_t b = 0; b < 32; ++b)
      if (got[b] != want[32 * n + b]) {
        printf("FAIL %s: record %lu (x=%u y=%u) byte %lu: 0x%02x, host 0x%02x\n", c->name,
               (unsigned long)n, records[n].x, records[n].y, (unsigned long)b, got[b],
               want[32 * n + b]);
        return 1;
      }
  }
  m4_flow_result r;
  m4_flow_estimate(records, c->pois, &c->params, &r);
  if (float_bits(r.flow_x) != c->flow_x_bits || float_bits(r.flow_y) != c->flow_y_bits ||
      r.quality != c->quality || r.meancount != c->meancount) {
    printf(
        "FAIL %s: estimate x=0x%08lx y=0x%08lx q=%ld n=%ld, host x=0x%08lx y=0x%08lx q=%ld "
        "n=%ld\n",
        c->name, (unsigned long)float_bits(r.flow_x), (unsigned long)float_bits(r.flow_y),
        (long)r.quality, (long)r.meancount, (unsigned long)c->flow_x_bits,
        (unsigned long)c->flow_y_bits, (long)c->quality, (long)c->meancount);
    return 1;
  }
  return 0;
}

int main(void) {
  initialise_monitor_handles();
  int failures = m4_selftest_simd();
  int failed_cases = 0;
  uint32_t pois = 0;
  for (uint32_t i = 0; i < M4_VEC_CASES; ++i) {
    failed_cases += check_case(&m4_vec_cases[i]);
    pois += m4_vec_cases[i].pois;
  }
  printf("kernel: %lu of %lu cases bit-exact (%lu POIs, records and estimate bits)\n",
         (unsigned long)(M4_VEC_CASES - (uint32_t)failed_cases), (unsigned long)M4_VEC_CASES,
         (unsigned long)pois);
  return failures + failed_cases;
}
