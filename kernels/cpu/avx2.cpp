// avx2: vmpsadbw on 256 bits runs two mpsadbw at once with a control per 128-bit lane. The
// candidate row's 16 bytes are broadcast to both lanes (a plain load); the low lane matches the
// block row's columns 0..3 at offsets dx..dx+3, the high lane its columns 4..7 at 4+dx.., so the
// sum of the two lanes is the row's SAD at 8 consecutive dx.
#include <immintrin.h>

#include "cpu_kernel.hpp"
#include "x86_argmin.hpp"
#include "x86_feature.hpp"
#include "x86_half_pixel.hpp"

namespace pxflow::cpu {
namespace {

constexpr int kMaxSide = 2 * kMaxSearchRadius + 1;
constexpr int kTableStride = 64;

int chunks_of_8(int radius) { return (2 * radius + 1 + 7) / 8; }

int row_bytes(int radius) {
  const int wide = 8 * (chunks_of_8(radius) - 1) + 17;
  return wide > 2 * radius + 10 ? wide : 2 * radius + 10;
}

// Low lane: block dword 0 against row offset 0 (bits 2:0 = 000); high lane: block dword 1
// against row offset 4 (bits 5:3 = 1,01).
constexpr int kLaneControl = (1 << 5) | (1 << 3);

BlockMatch search(Block prev, Window next, int radius, OpCounts*) {
  const int S = radius;
  const int chunks = chunks_of_8(S);
  __m256i block[8];
  for (int r = 0; r < 8; ++r)
    block[r] = _mm256_broadcastq_epi64(
        _mm_loadl_epi64(reinterpret_cast<const __m128i*>(prev.data + r * prev.stride)));
  alignas(32) std::uint16_t table[kMaxSide * kTableStride];
  for (int dy = 0; dy <= 2 * S; ++dy) {
    for (int c = 0; c < chunks; ++c) {
      const std::uint8_t* cand = next.data + (dy + 1) * next.stride + 1 + 8 * c;
      __m256i acc = _mm256_setzero_si256();
      for (int r = 0; r < 8; ++r) {
        const __m256i row = _mm256_broadcastsi128_si256(
            _mm_loadu_si128(reinterpret_cast<const __m128i*>(cand + r * next.stride)));
        acc = _mm256_add_epi16(acc, _mm256_mpsadbw_epu8(row, block[r], kLaneControl));
      }
      const __m128i sum =
          _mm_add_epi16(_mm256_castsi256_si128(acc), _mm256_extracti128_si256(acc, 1));
      _mm_store_si128(reinterpret_cast<__m128i*>(table + dy * kTableStride + 8 * c), sum);
    }
  }
  return table_minimum(table, S, kTableStride);
}

void half_pixel(Block prev, const std::uint8_t* around, std::ptrdiff_t stride, std::uint32_t sub[8],
                OpCounts*) {
  half_pixel_sse2(prev.data, prev.stride, around, stride, sub);
  // GCC may build the all-ones constant in a full-width register here without clearing the
  // upper halves on return; dirty upper state would slow every SSE instruction of the caller.
  _mm256_zeroupper();
}

}  // namespace

const IsaKernel& avx2_kernel() {
  static const IsaKernel k{"avx2", row_bytes, feature_sse2, search, half_pixel, false};
  return k;
}

}  // namespace pxflow::cpu
