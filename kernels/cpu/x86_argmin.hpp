// The first smallest SAD of a u16 table in raster order, with SSE4.1 (phminposuw). Included by
// the x86 kernels that fill a table (sse41, avx2, avx512bw), each compiling its own copy.
#pragma once
#include <smmintrin.h>

#include <cstddef>
#include <cstdint>

#include "cpu_kernel.hpp"

namespace pxflow::cpu {
namespace {

// Rows dy' = 0..2S of `stride` entries; entry dx' = 0..2S holds SAD(dx'-S, dy'-S). Entries
// beyond 2S in the last 8-wide chunk are whatever the kernel computed there: they are forced to
// 0xFFFF here, above any real SAD (<= 16,320), so they never win.
inline BlockMatch table_minimum(const std::uint16_t* table, int radius, std::ptrdiff_t stride) {
  const int side = 2 * radius + 1;
  const int chunks = (side + 7) / 8;
  const __m128i lane = _mm_setr_epi16(0, 1, 2, 3, 4, 5, 6, 7);
  const __m128i invalid =
      _mm_cmpgt_epi16(lane, _mm_set1_epi16(static_cast<short>(side - 1 - 8 * (chunks - 1))));
  auto chunk = [&](int r, int c) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(table + r * stride + 8 * c));
    return c == chunks - 1 ? _mm_or_si128(v, invalid) : v;
  };
  __m128i low = _mm_set1_epi16(-1);
  for (int r = 0; r < side; ++r)
    for (int c = 0; c < chunks; ++c) low = _mm_min_epu16(low, chunk(r, c));
  const int best = _mm_cvtsi128_si32(_mm_minpos_epu16(low)) & 0xFFFF;
  const __m128i target = _mm_set1_epi16(static_cast<short>(best));
  // Raster order: the first row, then the first chunk, then the lowest lane that holds it.
  for (int r = 0; r < side; ++r) {
    for (int c = 0; c < chunks; ++c) {
      const int hits = _mm_movemask_epi8(_mm_cmpeq_epi16(chunk(r, c), target));
      if (hits != 0) {
        const int dx = 8 * c + __builtin_ctz(static_cast<unsigned>(hits)) / 2;
        return {dx - radius, r - radius, static_cast<std::uint32_t>(best)};
      }
    }
  }
  return {0, 0, 0xFFFFFFFFu};  // unreachable: `best` came from the table
}

}  // namespace
}  // namespace pxflow::cpu
