// The eight half-pixel SADs of SPEC §3 step 3 with SSE2 intrinsics, shared by the x86 kernels.
// Included by each x86 ISA file, which compiles its own copy with its own flags (VEX-encoded in
// avx2.cpp and avx512bw.cpp); everything here is internal to that file (anonymous namespace).
//
// The floor average. _mm_avg_epu8 (pavgb) rounds UP: (a+b+1)>>1, which SPEC §7 forbids. On
// complemented bytes it rounds down: pavgb(~a, ~b) = ~floor((a+b)/2), exactly, for every a, b.
// So the pixels are complemented once when loaded and every average is a single pavgb; the
// SAD is unchanged by complementing both sides (|~a - ~b| = |a - b|), so prev's rows are
// complemented too and the results are never complemented back.
#pragma once
#include <emmintrin.h>

#include <cstddef>
#include <cstdint>

namespace pxflow::cpu {
namespace {

inline __m128i load8_complemented(const std::uint8_t* p) {
  return _mm_xor_si128(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p)), _mm_set1_epi8(-1));
}

// One row v of the matched block's neighbourhood, complemented: the 8 values P(0..7, v) and the
// horizontal averages h(-1..6, v) and h(0..7, v). Only the low 8 bytes of each are used.
struct HalfRow {
  __m128i p;        // ~P(c, v)
  __m128i h_left;   // ~h(c-1, v)
  __m128i h_right;  // ~h(c, v)
};

inline HalfRow half_row(const std::uint8_t* row_at_minus1) {
  const __m128i left = load8_complemented(row_at_minus1);
  const __m128i mid = load8_complemented(row_at_minus1 + 1);
  const __m128i right = load8_complemented(row_at_minus1 + 2);
  return {mid, _mm_avg_epu8(left, mid), _mm_avg_epu8(mid, right)};
}

// The vertical and diagonal values between rows v and v+1.
struct HalfPair {
  __m128i g;        // ~g(c, v)
  __m128i d_left;   // ~d(c-1, v): the average of two floored horizontal averages
  __m128i d_right;  // ~d(c, v)
};

inline HalfPair half_pair(const HalfRow& upper, const HalfRow& lower) {
  return {_mm_avg_epu8(upper.p, lower.p), _mm_avg_epu8(upper.h_left, lower.h_left),
          _mm_avg_epu8(upper.h_right, lower.h_right)};
}

// psadbw of two directions' rows (packed low|high) against prev's row in both halves.
inline __m128i sad_pair(__m128i a, __m128i b, __m128i prev_twice) {
  return _mm_sad_epu8(_mm_unpacklo_epi64(a, b), prev_twice);
}

// `around` is P(-1, -1); rows -1..8 and columns -1..8 are read, nothing else.
inline void half_pixel_sse2(const std::uint8_t* prev, std::ptrdiff_t prev_stride,
                            const std::uint8_t* around, std::ptrdiff_t stride,
                            std::uint32_t sub[8]) {
  __m128i acc01 = _mm_setzero_si128(), acc23 = acc01, acc45 = acc01, acc67 = acc01;
  HalfRow cur = half_row(around);  // row -1
  HalfPair above{};                // the pair (r-1, r) of the row being finished
  for (int v = 0; v <= 8; ++v) {
    const HalfRow next = half_row(around + (v + 1) * stride);
    const HalfPair below = half_pair(cur, next);  // the pair (v-1, v)
    if (v >= 1) {                                 // row r = v-1 has both its pairs now
      const std::uint8_t* prev_row = prev + (v - 1) * prev_stride;
      const __m128i q = load8_complemented(prev_row);
      const __m128i q2 = _mm_unpacklo_epi64(q, q);
      // SPEC §3 table: k0 h(c,r), k1 d(c,r), k2 g(c,r), k3 d(c-1,r), k4 h(c-1,r),
      // k5 d(c-1,r-1), k6 g(c,r-1), k7 d(c,r-1).
      acc01 = _mm_add_epi64(acc01, sad_pair(cur.h_right, below.d_right, q2));
      acc23 = _mm_add_epi64(acc23, sad_pair(below.g, below.d_left, q2));
      acc45 = _mm_add_epi64(acc45, sad_pair(cur.h_left, above.d_left, q2));
      acc67 = _mm_add_epi64(acc67, sad_pair(above.g, above.d_right, q2));
    }
    above = below;
    cur = next;
  }
  const __m128i accs[4] = {acc01, acc23, acc45, acc67};
  for (int k = 0; k < 4; ++k) {
    sub[2 * k] = static_cast<std::uint32_t>(_mm_cvtsi128_si32(accs[k]));
    sub[2 * k + 1] =
        static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_unpackhi_epi64(accs[k], accs[k])));
  }
}

}  // namespace
}  // namespace pxflow::cpu
