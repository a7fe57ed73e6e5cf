// sse2: the x86-64 baseline. psadbw compares 8 bytes per 64-bit half, so each candidate is four
// psadbw of two block rows against two candidate rows; the candidates are visited in raster
// order with the strict-smaller rule of SPEC §3, like the reference.
#include <emmintrin.h>

#include "cpu_kernel.hpp"
#include "x86_feature.hpp"
#include "x86_half_pixel.hpp"

namespace pxflow::cpu {
namespace {

int row_bytes(int radius) { return 2 * radius + 10; }  // 8-byte loads of needed pixels only

inline __m128i load8(const std::uint8_t* p) {
  return _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p));
}

inline __m128i two_rows(const std::uint8_t* p, std::ptrdiff_t stride) {
  return _mm_unpacklo_epi64(load8(p), load8(p + stride));
}

BlockMatch search(Block prev, Window next, int radius, OpCounts*) {
  const int S = radius;
  __m128i block[4];
  for (int q = 0; q < 4; ++q) block[q] = two_rows(prev.data + 2 * q * prev.stride, prev.stride);
  BlockMatch best{0, 0, 0xFFFFFFFFu};  // SPEC §3 sentinel
  for (int dy = -S; dy <= S; ++dy) {
    for (int dx = -S; dx <= S; ++dx) {
      const std::uint8_t* cand = next.data + (dy + S + 1) * next.stride + (dx + S + 1);
      __m128i acc = _mm_sad_epu8(block[0], two_rows(cand, next.stride));
      for (int q = 1; q < 4; ++q)
        acc = _mm_add_epi64(
            acc, _mm_sad_epu8(block[q], two_rows(cand + 2 * q * next.stride, next.stride)));
      acc = _mm_add_epi64(acc, _mm_unpackhi_epi64(acc, acc));
      const auto sad = static_cast<std::uint32_t>(_mm_cvtsi128_si32(acc));
      if (sad < best.sad) best = {dx, dy, sad};  // strict: ties keep the raster-order first
    }
  }
  return best;
}

void half_pixel(Block prev, const std::uint8_t* around, std::ptrdiff_t stride, std::uint32_t sub[8],
                OpCounts*) {
  half_pixel_sse2(prev.data, prev.stride, around, stride, sub);
}

}  // namespace

const IsaKernel& sse2_kernel() {
  static const IsaKernel k{"sse2", row_bytes, feature_sse2, search, half_pixel, false};
  return k;
}

}  // namespace pxflow::cpu
