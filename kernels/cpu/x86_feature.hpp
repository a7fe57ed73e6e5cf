// SPEC §3 step 1 with SSE2, shared by the x86 kernels (each compiles its own copy): the 24
// absolute differences of the central 4x4 in two psadbw instead of 24 scalar steps.
#pragma once
#include <emmintrin.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace pxflow::cpu {
namespace {

// `q` points at Q(0, 0) = prev(i+2, j+2).
inline std::uint16_t feature_sse2(const std::uint8_t* q, std::ptrdiff_t stride) {
  std::int32_t rows[4];
  for (int r = 0; r < 4; ++r) std::memcpy(&rows[r], q + r * stride, 4);
  const __m128i all = _mm_setr_epi32(rows[0], rows[1], rows[2], rows[3]);  // Q rows 0..3
  // Vertical neighbours: rows 0..2 against rows 1..3 (the fourth dword is 0 on both sides).
  const __m128i upper = _mm_and_si128(all, _mm_setr_epi32(-1, -1, -1, 0));
  const __m128i lower = _mm_srli_si128(all, 4);
  // Horizontal neighbours: columns 0..2 against 1..3 of each row; column 3 is 0 on both sides.
  const __m128i left = _mm_and_si128(all, _mm_set1_epi32(0x00FFFFFF));
  const __m128i right = _mm_srli_epi32(all, 8);
  const __m128i sums = _mm_add_epi64(_mm_sad_epu8(upper, lower), _mm_sad_epu8(left, right));
  return static_cast<std::uint16_t>(_mm_cvtsi128_si32(sums) +
                                    _mm_cvtsi128_si32(_mm_unpackhi_epi64(sums, sums)));
}

}  // namespace
}  // namespace pxflow::cpu
