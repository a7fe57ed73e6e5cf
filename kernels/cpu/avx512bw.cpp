// avx512bw: vdbpsadbw (_mm512_dbsad_epu8) computes 32 SADs of 4-byte groups per instruction,
// twice the work of a 512-bit psadbw. Per 128-bit lane, with control 0x94, it gives the SADs
// of one 4-byte group of the block (repeated across the lane) against 8 consecutive offsets of
// 16 candidate-row bytes. The four lanes cover the block row's two halves at 16 consecutive dx:
//
//   lane 0: columns 0..3 vs row bytes 0..   (dx' 0..7)     lane 1: columns 0..3 vs 8..  (dx' 8..15)
//   lane 2: columns 4..7 vs row bytes 4..   (dx' 0..7)     lane 3: columns 4..7 vs 12.. (dx' 8..15)
//
// so the low and high 256 bits add up to the row's SAD at 16 dx. A candidate row is one masked
// load (only the bytes the window holds: masked lanes never fault, so no copy at the frame's
// edge) and one vpermd that spreads it over the lanes; eight of them, for the eight block rows,
// slide down the window one row per dy.
#include <immintrin.h>

#include "cpu_kernel.hpp"

// GCC 12's avx512fintrin.h passes "undefined" vectors as the unused merge source of
// _mm512_permutexvar_epi32 and _mm512_extracti64x4_epi64, which -Wuninitialized reports at
// every use. The instructions take no merge source; the warnings are false.
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include "x86_argmin.hpp"
#include "x86_half_pixel.hpp"

namespace pxflow::cpu {
namespace {

constexpr int kMaxSide = 2 * 31 + 1;
constexpr int kTableStride = 64;     // 4 chunks of 16 dx
constexpr int kGroupControl = 0x94;  // dwords (0,1) and (1,2) of each lane: 8 offsets

int chunks_of_16(int radius) { return (2 * radius + 1 + 15) / 16; }

int row_bytes(int radius) { return 2 * radius + 10; }  // masked loads read needed bytes only

struct RowLoader {
  const std::uint8_t* base;  // window column 1 + 16c, row 0
  std::ptrdiff_t stride;
  __mmask64 needed;  // the bytes of the chunk that dx' <= 2S can reach
  __m512i spread;

  __m512i row(int window_row) const {
    const __m512i bytes = _mm512_maskz_loadu_epi8(needed, base + window_row * stride);
    return _mm512_permutexvar_epi32(spread, bytes);
  }
};

inline __m512i row_sad(const __m512i block[8], const __m512i cand[8]) {
  const __m512i s01 = _mm512_add_epi16(_mm512_dbsad_epu8(block[0], cand[0], kGroupControl),
                                       _mm512_dbsad_epu8(block[1], cand[1], kGroupControl));
  const __m512i s23 = _mm512_add_epi16(_mm512_dbsad_epu8(block[2], cand[2], kGroupControl),
                                       _mm512_dbsad_epu8(block[3], cand[3], kGroupControl));
  const __m512i s45 = _mm512_add_epi16(_mm512_dbsad_epu8(block[4], cand[4], kGroupControl),
                                       _mm512_dbsad_epu8(block[5], cand[5], kGroupControl));
  const __m512i s67 = _mm512_add_epi16(_mm512_dbsad_epu8(block[6], cand[6], kGroupControl),
                                       _mm512_dbsad_epu8(block[7], cand[7], kGroupControl));
  return _mm512_add_epi16(_mm512_add_epi16(s01, s23), _mm512_add_epi16(s45, s67));
}

void search_chunk(const __m512i block[8], const RowLoader& loader, int radius,
                  std::uint16_t* column) {
  __m512i cand[8];
  for (int r = 0; r < 8; ++r) cand[r] = loader.row(r + 1);
  for (int dy = 0; dy <= 2 * radius; ++dy) {
    const __m512i acc = row_sad(block, cand);
    const __m256i sum =
        _mm256_add_epi16(_mm512_castsi512_si256(acc), _mm512_extracti64x4_epi64(acc, 1));
    _mm256_store_si256(reinterpret_cast<__m256i*>(column + dy * kTableStride), sum);
    if (dy == 2 * radius) break;
    for (int r = 0; r < 7; ++r) cand[r] = cand[r + 1];
    cand[7] = loader.row(dy + 9);
  }
}

BlockMatch search(Block prev, Window next, OpCounts*) {
  const int S = next.radius;
  const __m512i halves = _mm512_setr_epi32(0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1);
  __m512i block[8];
  for (int r = 0; r < 8; ++r) {
    const __m128i row =
        _mm_loadl_epi64(reinterpret_cast<const __m128i*>(prev.data + r * prev.stride));
    block[r] = _mm512_permutexvar_epi32(halves, _mm512_zextsi128_si512(row));
  }
  alignas(32) std::uint16_t table[kMaxSide * kTableStride];
  for (int c = 0; c < chunks_of_16(S); ++c) {
    const int last_dx = (2 * S - 16 * c < 15) ? 2 * S - 16 * c : 15;
    const RowLoader loader{next.data + 1 + 16 * c, next.stride, (1ull << (last_dx + 8)) - 1,
                           _mm512_setr_epi32(0, 1, 2, 3, 2, 3, 4, 5, 1, 2, 3, 4, 3, 4, 5, 6)};
    search_chunk(block, loader, S, table + 16 * c);
  }
  return table_minimum(table, S, kTableStride);
}

void half_pixel(Block prev, const std::uint8_t* around, std::ptrdiff_t stride, std::uint32_t sub[8],
                OpCounts*) {
  half_pixel_sse2(prev.data, prev.stride, around, stride, sub);
}

}  // namespace

const IsaKernel& avx512bw_kernel() {
  static const IsaKernel k{"avx512bw", row_bytes, search, half_pixel, false};
  return k;
}

}  // namespace pxflow::cpu
