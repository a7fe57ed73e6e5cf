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

#include <cstring>

#include "cpu_kernel.hpp"
#include "x86_feature.hpp"

// GCC 12's avx512fintrin.h passes "undefined" vectors as the unused merge source of
// _mm512_permutexvar_epi32 and _mm512_extracti64x4_epi64, which -Wuninitialized reports at
// every use. The instructions take no merge source; the warnings are false.
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

namespace pxflow::cpu {
namespace {

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

// The first minimum in raster order without a table: each candidate becomes the key
// sad << 12 | (dy' * 64 + dx'), which orders by SAD first and then by raster position (the
// tie rule of SPEC §3), and one vpminud per row keeps the smallest. Candidates beyond dx' = 2S
// get all-ones keys. sad <= 16,320 and the position < 4,096, so a key fits 26 bits.
constexpr int kPositionBits = 12;
constexpr int kRowPositions = 64;

void search_chunk(const __m512i block[8], const RowLoader& loader, int radius, int chunk,
                  __m512i& best) {
  const __m512i lanes = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const int valid = 2 * radius + 1 - 16 * chunk;  // dx' of this chunk that exist
  const __mmask16 beyond = static_cast<__mmask16>(valid >= 16 ? 0 : 0xFFFF << valid);
  const __m512i invalid = _mm512_maskz_set1_epi32(beyond, -1);
  __m512i position = _mm512_add_epi32(lanes, _mm512_set1_epi32(16 * chunk));
  __m512i cand[8];
  for (int r = 0; r < 8; ++r) cand[r] = loader.row(r + 1);
  for (int dy = 0; dy <= 2 * radius; ++dy) {
    const __m512i acc = row_sad(block, cand);
    const __m256i sum =
        _mm256_add_epi16(_mm512_castsi512_si256(acc), _mm512_extracti64x4_epi64(acc, 1));
    const __m512i sad = _mm512_slli_epi32(_mm512_cvtepu16_epi32(sum), kPositionBits);
    best = _mm512_min_epu32(best, _mm512_ternarylogic_epi32(sad, position, invalid, 0xFE));
    if (dy == 2 * radius) break;
    position = _mm512_add_epi32(position, _mm512_set1_epi32(kRowPositions));
    for (int r = 0; r < 7; ++r) cand[r] = cand[r + 1];
    cand[7] = loader.row(dy + 9);
  }
}

BlockMatch search(Block prev, Window next, int radius, OpCounts*) {
  const int S = radius;
  const __m512i halves = _mm512_setr_epi32(0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1);
  __m512i block[8];
  for (int r = 0; r < 8; ++r) {
    const __m128i row =
        _mm_loadl_epi64(reinterpret_cast<const __m128i*>(prev.data + r * prev.stride));
    block[r] = _mm512_permutexvar_epi32(halves, _mm512_zextsi128_si512(row));
  }
  __m512i best = _mm512_set1_epi32(-1);
  for (int c = 0; c < chunks_of_16(S); ++c) {
    const int last_dx = (2 * S - 16 * c < 15) ? 2 * S - 16 * c : 15;
    const RowLoader loader{next.data + 1 + 16 * c, next.stride, (1ull << (last_dx + 8)) - 1,
                           _mm512_setr_epi32(0, 1, 2, 3, 2, 3, 4, 5, 1, 2, 3, 4, 3, 4, 5, 6)};
    search_chunk(block, loader, S, c, best);
  }
  const auto key = static_cast<std::uint32_t>(_mm512_reduce_min_epu32(best));
  const std::uint32_t position = key & ((1u << kPositionBits) - 1);
  _mm256_zeroupper();
  return {static_cast<int>(position % kRowPositions) - S,
          static_cast<int>(position / kRowPositions) - S, key >> kPositionBits};
}

// SPEC §3 step 3 with the eight block rows as the eight qwords of a zmm: psadbw then gives one
// direction's eight row SADs at once. The rows are gathered through a small stack buffer (three
// column offsets u = -1, 0, +1 of rows -1..8), complemented so that pavgb floors (see
// x86_half_pixel.hpp), averaged plane by plane, and the eight direction sums are reduced
// together, four u16 fields per qword (a field's sum is at most 16,320: no carry).
void half_pixel(Block prev, const std::uint8_t* around, std::ptrdiff_t stride, std::uint32_t sub[8],
                OpCounts*) {
  alignas(64) std::uint64_t planes[3][10];  // planes[s][v + 1]: row v from column s - 1
  alignas(64) std::uint64_t block[8];
  for (int v = 0; v < 10; ++v)
    for (int s = 0; s < 3; ++s) std::memcpy(&planes[s][v], around + v * stride + s, 8);
  for (int r = 0; r < 8; ++r) std::memcpy(&block[r], prev.data + r * prev.stride, 8);
  const __m512i ones = _mm512_set1_epi8(-1);
  // Rows r + t (r = 0..7) of plane s, complemented.
  auto rows = [&](int s, int t) {
    return _mm512_xor_si512(_mm512_loadu_si512(&planes[s][t + 1]), ones);
  };
  const __m512i p_up = rows(1, -1), p_mid = rows(1, 0), p_down = rows(1, 1);
  const __m512i hl_up = _mm512_avg_epu8(rows(0, -1), p_up);  // ~h(c-1, r-1)
  const __m512i hr_up = _mm512_avg_epu8(p_up, rows(2, -1));  // ~h(c, r-1)
  const __m512i hl = _mm512_avg_epu8(rows(0, 0), p_mid);
  const __m512i hr = _mm512_avg_epu8(p_mid, rows(2, 0));
  const __m512i hl_down = _mm512_avg_epu8(rows(0, 1), p_down);
  const __m512i hr_down = _mm512_avg_epu8(p_down, rows(2, 1));
  const __m512i q = _mm512_xor_si512(_mm512_load_si512(block), ones);
  const __m512i s[8] = {_mm512_sad_epu8(hr, q),                              // k0 h(c, r)
                        _mm512_sad_epu8(_mm512_avg_epu8(hr, hr_down), q),    // k1 d(c, r)
                        _mm512_sad_epu8(_mm512_avg_epu8(p_mid, p_down), q),  // k2 g(c, r)
                        _mm512_sad_epu8(_mm512_avg_epu8(hl, hl_down), q),    // k3 d(c-1, r)
                        _mm512_sad_epu8(hl, q),                              // k4 h(c-1, r)
                        _mm512_sad_epu8(_mm512_avg_epu8(hl_up, hl), q),      // k5 d(c-1, r-1)
                        _mm512_sad_epu8(_mm512_avg_epu8(p_up, p_mid), q),    // k6 g(c, r-1)
                        _mm512_sad_epu8(_mm512_avg_epu8(hr_up, hr), q)};     // k7 d(c, r-1)
  for (int half = 0; half < 2; ++half) {
    const __m512i* d = s + 4 * half;
    const __m512i packed =
        _mm512_or_si512(_mm512_or_si512(d[0], _mm512_slli_epi64(d[1], 16)),
                        _mm512_or_si512(_mm512_slli_epi64(d[2], 32), _mm512_slli_epi64(d[3], 48)));
    const auto sums = static_cast<std::uint64_t>(_mm512_reduce_add_epi64(packed));
    for (int k = 0; k < 4; ++k) sub[4 * half + k] = (sums >> (16 * k)) & 0xFFFF;
  }
  _mm256_zeroupper();
}

}  // namespace

const IsaKernel& avx512bw_kernel() {
  static const IsaKernel k{"avx512bw", row_bytes, feature_sse2, search, half_pixel, false};
  return k;
}

}  // namespace pxflow::cpu
