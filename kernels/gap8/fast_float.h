/* SPEC §5's float steps in integer arithmetic (the fast variant's estimate, fast_serial.c; beyond
 * the paper). The cores have no FPU: the spec core's estimate runs libgcc's soft-float (__divsf3,
 * __subsf3, __floatsisf), about 4k cycles on core 0 after the join, most of them cold misses of
 * the instruction cache. These helpers give the same IEEE-754 bits from integers: each float
 * operation of the spec is exact or rounds once to nearest even, so the exact rational result,
 * rounded once here, is that operation's result.
 *
 * Domain: integers below 2^24 (exact in float) and divisors below 2^12. The kernel's are
 * smaller: a record takes 32 bytes of the 64 KiB L1, so there are < 2048 POIs, hence V <=
 * 126 * 2048 < 2^18, Wt and 2 * count < 2^12, |sum of hx| <= 63 * 2048 < 2^17. Plain C (no
 * Xpulp), so the host test checks it against the host's float arithmetic
 * (tests/gap8/test_gap8_fast_float.cpp). */
#ifndef PXFLOW_GAP8_FAST_FLOAT_H
#define PXFLOW_GAP8_FAST_FLOAT_H

#include <stdint.h>

/* A positive value m * 2^e with m < 2^24 (a float's significand) or m = 0. */
typedef struct {
  uint32_t m;
  int32_t e;
} fast_fp;

/* Position of the highest set bit of v != 0 (a binary search: __builtin_clz would call libgcc's
 * __clzsi2, whose table is in L2). */
static inline int32_t fast_top_bit(uint64_t v) {
  int32_t t = 0;
  if (v >> 32) v >>= 32, t += 32;
  uint32_t w = (uint32_t)v;
  if (w >> 16) w >>= 16, t += 16;
  if (w >> 8) w >>= 8, t += 8;
  if (w >> 4) w >>= 4, t += 4;
  if (w >> 2) w >>= 2, t += 2;
  if (w >> 1) t += 1;
  return t;
}

/* Not inlined, here and in fast_div: one copy of each keeps the code of the serial estimate, whose
 * every line is a cold miss of the instruction cache (12 cycles per 16 bytes), small. */
/* (m + f) * 2^e rounded to 24 bits, to nearest, ties to even; m > 0, 0 <= f < 1 with sticky = (f
 * != 0). When m has fewer than 25 bits, sticky must be 0 (the callers give at least 32). */
static __attribute__((noinline)) fast_fp fast_round(uint64_t m, int32_t e, uint32_t sticky) {
  const int32_t t = fast_top_bit(m);
  fast_fp r;
  if (t <= 23) { /* exact: shift up */
    r.m = (uint32_t)m << (23 - t);
    r.e = e - (23 - t);
    return r;
  }
  const int32_t s = t - 23;
  const uint64_t half = (uint64_t)1 << (s - 1);
  const uint64_t rest = m & ((half << 1) - 1);
  uint32_t keep = (uint32_t)(m >> s);
  /* above half, or exactly half and odd (a tie goes to the even neighbour) */
  if (rest > half || (rest == half && (sticky || (keep & 1)))) ++keep;
  r.m = keep;
  r.e = e + s;
  if (keep >> 24) { /* rounded up to 2^24 */
    r.m = keep >> 1;
    r.e += 1;
  }
  return r;
}

/* fl(n / d) for 0 < n < 2^24, 0 < d < 2^12: n normalised to 24 bits, then two steps of long
 * division, Q = floor(n' * 2^20 / d) = q1 * 2^20 + floor(r1 * 2^20 / d) (r1 < d < 2^12, so r1 *
 * 2^20 < 2^32); Q has >= 31 bits (q1 >= 2^23 / 2^12), the last remainder gives the sticky bit. */
static __attribute__((noinline)) fast_fp fast_div(uint32_t n, uint32_t d) {
  const int32_t a = 23 - fast_top_bit(n);
  const uint32_t nn = n << a; /* in [2^23, 2^24) */
  const uint32_t q1 = nn / d, t = (nn - q1 * d) << 20;
  const uint32_t q0 = t / d;
  return fast_round((uint64_t)q1 << 20 | q0, -20 - a, t - q0 * d != 0);
}

/* The float bits of sign * v * 2^-1 (the spec's exact halving: no subnormals here), 0 for v.m = 0.
 */
static inline uint32_t fast_bits_half(fast_fp v, uint32_t negative) {
  if (v.m == 0) return 0; /* +0: x - x and 0 / y are +0 in round to nearest */
  const uint32_t exponent = (uint32_t)(v.e - 1 + 23 + 127);
  return (negative ? 0x80000000u : 0u) | exponent << 23 | (v.m & 0x7FFFFFu);
}

/* HF: (fl(V / Wt) - (float)k) / 2.0f, as float bits (k = 2S + 1, the subtraction rounds once). */
static inline uint32_t fast_filtered_bits(uint32_t value, uint32_t weight, uint32_t k) {
  int64_t diff = -(int64_t)k; /* V = 0: q = 0, q - k = -k */
  int32_t e = 0;
  if (value) {
    const fast_fp q = fast_div(value, weight); /* q = q.m * 2^q.e, q.e >= -40 */
    e = q.e < 0 ? q.e : 0;
    diff = ((int64_t)q.m << (q.e - e)) - ((int64_t)k << -e); /* exact, |.| < 2^48 */
  }
  fast_fp r = {0, 0};
  if (diff) r = fast_round((uint64_t)(diff < 0 ? -diff : diff), e, 0);
  return fast_bits_half(r, diff < 0);
}

/* HF off: ((float)sum / 2.0f) / (float)count, as float bits: sum / 2 is exact, so the result is
 * sum / (2 count) rounded once. */
static inline uint32_t fast_mean_bits(int32_t sum, uint32_t count) {
  if (sum == 0) return 0;
  const fast_fp q = fast_div((uint32_t)(sum < 0 ? -sum : sum), 2 * count);
  const fast_fp doubled = {q.m, q.e + 1}; /* fast_bits_half halves it back */
  return fast_bits_half(doubled, sum < 0);
}

#endif
