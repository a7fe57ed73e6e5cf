// sse41: mpsadbw computes the SADs of one 4-byte group of the block against 8 consecutive
// positions of a candidate row: one instruction covers 8 dx candidates of half a block row.
// The SADs go to a table (one u16 row per dy, 8 dx per chunk) and phminposuw finds the first
// minimum in raster order.
#include <smmintrin.h>

#include "cpu_kernel.hpp"
#include "x86_argmin.hpp"
#include "x86_feature.hpp"
#include "x86_half_pixel.hpp"

namespace pxflow::cpu {
namespace {

constexpr int kMaxSide = 2 * kMaxSearchRadius + 1;
constexpr int kTableStride = 64;  // entries per table row: 8 chunks of 8 dx

int chunks_of_8(int radius) { return (2 * radius + 1 + 7) / 8; }

// Chunk c loads 16 bytes from window column 1 + 8c.
int row_bytes(int radius) {
  const int wide = 8 * (chunks_of_8(radius) - 1) + 17;
  return wide > 2 * radius + 10 ? wide : 2 * radius + 10;
}

inline __m128i load16(const std::uint8_t* p) {
  return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
}

BlockMatch search(Block prev, Window next, int radius, OpCounts*) {
  const int S = radius;
  const int chunks = chunks_of_8(S);
  __m128i block[8];  // dword 0: columns 0..3 of row r, dword 1: columns 4..7
  for (int r = 0; r < 8; ++r)
    block[r] = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(prev.data + r * prev.stride));
  alignas(16) std::uint16_t table[kMaxSide * kTableStride];
  for (int dy = 0; dy <= 2 * S; ++dy) {
    for (int c = 0; c < chunks; ++c) {
      const std::uint8_t* cand = next.data + (dy + 1) * next.stride + 1 + 8 * c;
      __m128i acc = _mm_setzero_si128();
      for (int r = 0; r < 8; ++r) {
        const __m128i row = load16(cand + r * next.stride);
        // imm 0: columns 0..3 against row bytes dx..dx+3; imm 5: columns 4..7 against 4+dx..
        acc = _mm_add_epi16(acc, _mm_mpsadbw_epu8(row, block[r], 0));
        acc = _mm_add_epi16(acc, _mm_mpsadbw_epu8(row, block[r], 5));
      }
      _mm_store_si128(reinterpret_cast<__m128i*>(table + dy * kTableStride + 8 * c), acc);
    }
  }
  return table_minimum(table, S, kTableStride);
}

void half_pixel(Block prev, const std::uint8_t* around, std::ptrdiff_t stride, std::uint32_t sub[8],
                OpCounts*) {
  half_pixel_sse2(prev.data, prev.stride, around, stride, sub);
}

}  // namespace

const IsaKernel& sse41_kernel() {
  static const IsaKernel k{"sse41", row_bytes, feature_sse2, search, half_pixel, false};
  return k;
}

}  // namespace pxflow::cpu
