/* The self-test firmware: the DSP semantics (m4_selftest_simd.c), then every generated case
 * (m4_vectors.h): the kernel's records against the host reference's, byte for byte, and the
 * estimate the DUT firmware sends (dut/'s pxdut_estimate_flow, compiled here for the FPU with the
 * firmware's flags) against the host's float bits. One line per failure, a summary, and the
 * number of failures as QEMU's exit status (semihosting). */
#include <stdio.h>
#include <string.h>

#include "board.h"
#include "m4_flow.h"
#include "m4_selftest.h"
#include "m4_vectors.h"
#include "pxdut.h"

extern void initialise_monitor_handles(void); /* newlib's rdimon: semihosted stdio */

#define MAX_POIS 1024u
static pxflow_poi_record records[MAX_POIS];

static uint32_t float_bits(float f) {
  uint32_t u;
  memcpy(&u, &f, 4);
  return u;
}

static int check_case(const m4_vec_case *c) {
  const uint8_t *prev = m4_vec_pixels + c->pixels;
  const uint8_t *next = prev + c->params.width * c->params.height;
  if (pxflow_check_params(&c->params) != PXFLOW_PARAMS_OK ||
      pxflow_poi_count(&c->params) != c->pois || c->pois > MAX_POIS) {
    printf("FAIL %s: parameters or POI count disagree with the host\n", c->name);
    return 1;
  }
  memset(records, 0xA5, sizeof records); /* a sentinel: an unwritten byte shows */
  m4_flow_frame(&c->params, prev, next, records);
  const uint8_t *want = m4_vec_records + PXFLOW_RECORD_BYTES * c->records;
  for (uint32_t n = 0; n < c->pois; ++n) {
    const uint8_t *got = (const uint8_t *)&records[n];
    for (uint32_t b = 0; b < PXFLOW_RECORD_BYTES; ++b)
      if (got[b] != want[PXFLOW_RECORD_BYTES * n + b]) {
        printf("FAIL %s: record %lu (x=%u y=%u) byte %lu: 0x%02x, host 0x%02x\n", c->name,
               (unsigned long)n, records[n].x, records[n].y, (unsigned long)b, got[b],
               want[PXFLOW_RECORD_BYTES * n + b]);
        return 1;
      }
  }
  pxdut_estimate r;
  pxdut_estimate_flow(records, c->pois, &c->params, &r); /* the spec core's types on both sides */
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

/* The counter measures instructions under -icount shift=3: a loop of exactly 2 * n instructions
 * (SUBS, BNE) between two readings must read 2n / 5 SysTick ticks (8 ns per instruction, 40 ns
 * per 25 MHz tick), plus the few instructions of the readings themselves. */
static int check_instruction_count(void) {
  const uint32_t n = 1000000u;
  uint32_t k = n;
  const uint64_t t0 = board_systick_ticks();
  __asm__ volatile("1: subs %0, %0, #1\n\tbne 1b" : "+r"(k) : : "cc");
  const uint64_t insns = (board_systick_ticks() - t0) * 5u;
  const int ok = insns >= 2u * n && insns <= 2u * n + 50u;
  printf("%s counter: %lu instructions measured for a loop of %lu (expected %lu + at most 50)\n",
         ok ? "ok" : "FAIL", (unsigned long)insns, (unsigned long)(2u * n),
         (unsigned long)(2u * n));
  return ok ? 0 : 1;
}

int main(void) {
  initialise_monitor_handles();
  board_systick_init();
  int failures = check_instruction_count();
  failures += m4_selftest_simd();
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
