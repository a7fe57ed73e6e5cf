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

#include <cstddef>
#include <utility>

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

// Two POIs of one grid row per vdbpsadbw, for 2S + 1 <= 9: the lanes hold (POI a, columns 0..3),
// (a, columns 4..7), (b, columns 0..3), (b, columns 4..7), each at dx' 0..7 (a window row's bytes
// from 0 and from 4), so no lane computes a dx' beyond 2S but the ninth, dx' = 8 at S = 4,
// which pair_column adds per POI. A candidate row is one masked load per POI and one
// vpermt2d for both, where the 16-dx' layout spends a vpermd per POI.
struct PairLoader {
  const std::uint8_t* a;  // POI a's window column 1, row 0
  const std::uint8_t* b;
  std::ptrdiff_t stride;
  __mmask64 needed;  // bytes 0 .. last dx' + 7
  // Plain 16-byte loads instead of masked ones: for S >= 4, where the 16 bytes stay within the
  // kernel's row_bytes (a masked byte load cost Zen 4 about a cycle of a vector pipe). The byte
  // after the last dx' + 7 is never compared (see the lanes above).
  bool whole;

  __m512i load(const std::uint8_t* p) const {
    return whole ? _mm512_zextsi128_si512(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)))
                 : _mm512_maskz_loadu_epi8(needed, p);
  }
  __m512i row(int window_row) const {
    const __m512i spread =
        _mm512_setr_epi32(0, 1, 2, 3, 1, 2, 3, 4, 16, 17, 18, 19, 17, 18, 19, 20);
    return _mm512_permutex2var_epi32(load(a + window_row * stride), spread,
                                     load(b + window_row * stride));
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
// sad << 16 | (dy' * 64 + dx'), which orders by SAD first and then by raster position (the tie
// rule of SPEC §3), and vpminud keeps the smallest. sad <= 16,320 and the position < 4,096.
//
// Two rows dy', dy'+1 are keyed together, without widening: their sums a and b become
// H = [a.lo + a.hi | b.lo + b.hi] (two vshufi64x2 and one add: u16 lane j holds dx' = j of
// dy', lane 16 + j dx' = j of dy' + 1). Each u16 lane keeps its least sum so far and that sum's
// position (a vpcmpuw and two masked moves per pair of rows: a later row replaces it only when
// strictly smaller, so each lane keeps its first minimum), and only after the last row are the
// lanes widened to keys: H << 16 for the even lanes, H & 0xFFFF0000 for the odd ones, each
// ORed with its position. Lanes beyond dx' = 2S (and the missing row after the last, 2S + 1
// being odd) are masked out of the comparisons. Per pair of rows this is one shuffle per row
// instead of the extract and the zero extension each row took, both on the port vdbpsadbw and
// vpermd need, and three operations where keying each row took five.
constexpr int kPositionBits = 16;
constexpr int kRowPositions = 64;

struct Keys {
  __m512i even = _mm512_set1_epi32(-1);
  __m512i odd = _mm512_set1_epi32(-1);
};

template <class Loader>
inline void slide(__m512i cand[8], const Loader& loader, int window_row) {
  for (int r = 0; r < 7; ++r) cand[r] = cand[r + 1];
  cand[7] = loader.row(window_row);
}

// Keys the rows dy' = 0..2S of `loader`'s candidates into `best`. A row's sums come out of
// row_sad as four lanes of 8 u16; kLow and kHigh (vshufi64x2 immediates) pick from two rows a and
// b the lanes that are added, so that H holds 32 u16 sums whose dword i has the raster position
// `position` (+ 2 * kRowPositions per pair of rows) for its even u16 and that + 1 for its odd one.
//
// kRadius > 0 fixes S at compile time: the loop over dy' is then unrolled and the eight candidate
// rows stay in registers as they slide (with S known only at run time, GCC keeps them on the
// stack and copies them at every slide).
template <class Loader, int kLow, int kHigh, int kRadius = 0>
[[gnu::always_inline]] inline void key_rows(const __m512i block[8], const Loader& loader,
                                            int runtime_radius, __m512i position, __mmask16 even_ok,
                                            __mmask16 odd_ok, Keys& best) {
  const int radius = kRadius > 0 ? kRadius : runtime_radius;
  // u16 lane 2i: dword i's even_ok bit, lane 2i + 1: its odd_ok bit (shifted as 64-bit values,
  // so that no shift count reaches its operand's width).
  __mmask32 valid = 0;
  for (int i = 0; i < 16; ++i)
    valid |= static_cast<__mmask32>((std::uint64_t{(even_ok >> i) & 1u} << (2 * i)) |
                                    (std::uint64_t{(odd_ok >> i) & 1u} << (2 * i + 1)));
  // Each u16 lane's position (dword i of `position` and that + 1), its least sum and where.
  __m512i at = _mm512_or_si512(
      position, _mm512_slli_epi32(_mm512_add_epi32(position, _mm512_set1_epi32(1)), 16));
  __m512i least = _mm512_set1_epi16(-1), where = _mm512_setzero_si512();
  __m512i cand[8];
  for (int r = 0; r < 8; ++r) cand[r] = loader.row(r + 1);
#pragma GCC unroll 16
  for (int dy = 0; dy <= 2 * radius; dy += 2) {
    const __m512i a = row_sad(block, cand);
    __m512i b = a;
    __mmask32 rows = 0xFFFFFFFFu;
    if (dy < 2 * radius) {
      slide(cand, loader, dy + 9);
      b = row_sad(block, cand);
    } else {
      rows = 0x0000FFFFu;  // no row dy' + 1 (u16 lanes 16..31 of H belong to it)
    }
    const __m512i h =
        _mm512_add_epi16(_mm512_shuffle_i64x2(a, b, kLow), _mm512_shuffle_i64x2(a, b, kHigh));
    const __mmask32 less = _mm512_mask_cmplt_epu16_mask(valid & rows, h, least);
    least = _mm512_mask_mov_epi16(least, less, h);
    where = _mm512_mask_mov_epi16(where, less, at);
    if (dy + 1 >= 2 * radius) break;
    slide(cand, loader, dy + 10);
    at = _mm512_add_epi16(at, _mm512_set1_epi16(2 * kRowPositions));
  }
  // Lanes never valid keep sum 0xFFFF, above any SAD: their keys never win.
  const __m512i low = _mm512_set1_epi32(0xFFFF);
  const __m512i even = _mm512_ternarylogic_epi32(_mm512_slli_epi32(least, kPositionBits), where,
                                                 low, 0xF8);  // least << 16 | (where & low)
  const __m512i odd =
      _mm512_ternarylogic_epi32(least, _mm512_set1_epi32(static_cast<int>(0xFFFF0000u)),
                                _mm512_srli_epi32(where, kPositionBits), 0xEA);  // & high | >> 16
  best.even = _mm512_min_epu32(best.even, even);
  best.odd = _mm512_min_epu32(best.odd, odd);
}

// Dwords whose even (odd) u16 holds an existing dx': dword i of each 128-bit lane holds
// dx' = first + 2i and first + 2i + 1 (`lane_step`: how much first grows from lane to lane,
// `lanes_per_row`: after how many lanes it starts again).
struct DxMasks {
  __mmask16 even = 0, odd = 0;
};

DxMasks dx_masks(int valid, int lane_step, int lanes_per_row) {
  DxMasks m;
  for (int d = 0; d < 16; ++d) {
    const int dx = lane_step * ((d / 4) % lanes_per_row) + 2 * (d % 4);
    if (dx < valid) m.even = static_cast<__mmask16>(m.even | (1u << d));
    if (dx + 1 < valid) m.odd = static_cast<__mmask16>(m.odd | (1u << d));
  }
  return m;
}

template <int kRadius>
[[gnu::always_inline]] inline void search_chunk(const __m512i block[8], const RowLoader& loader,
                                                int radius, int chunk, Keys& best) {
  // Dword i: u16 lanes 2i and 2i + 1 of H, i.e. dx' = 2 (i mod 8) of row dy' + i / 8.
  const __m512i pairs =
      _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, kRowPositions + 0, kRowPositions + 2,
                        kRowPositions + 4, kRowPositions + 6, kRowPositions + 8, kRowPositions + 10,
                        kRowPositions + 12, kRowPositions + 14);
  const DxMasks ok = dx_masks(2 * radius + 1 - 16 * chunk, 8, 2);  // dx' of this chunk that exist
  key_rows<RowLoader, 0x44, 0xEE, kRadius>(  // H = [a.lo + a.hi | b.lo + b.hi]
      block, loader, radius, _mm512_add_epi32(pairs, _mm512_set1_epi32(16 * chunk)), ok.even,
      ok.odd, best);
}

// Two rows of 8 bytes, row r of `p + r * stride` in qword r of an xmm.
inline __m128i two_rows(const std::uint8_t* p, std::ptrdiff_t stride) {
  return _mm_unpacklo_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p)),
                            _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p + stride)));
}

// Eight rows of 8 bytes, row r of `p + r * stride` in qword r: pairs of rows put together by
// vinserti128 and vinserti64x4, no store to a stack buffer that a 64-byte load would then have
// to wait for (a failed store forward per plane cost more than the SADs). Each row merged by a
// masked vpbroadcastq was 5-7 % slower on Zen 4 (S = 4 and 8), where a merge costs as much as a
// 512-bit shuffle.
inline __m512i qword_rows(const std::uint8_t* p, std::ptrdiff_t stride) {
  const __m256i lo = _mm256_inserti128_si256(_mm256_castsi128_si256(two_rows(p, stride)),
                                             two_rows(p + 2 * stride, stride), 1);
  const __m256i hi =
      _mm256_inserti128_si256(_mm256_castsi128_si256(two_rows(p + 4 * stride, stride)),
                              two_rows(p + 6 * stride, stride), 1);
  return _mm512_inserti64x4(_mm512_castsi256_si512(lo), hi, 1);
}

// The eight totals of eight vectors of eight qword SADs (psadbw results, each qword <= 2,040,
// a total <= 16,320), as the u16 lanes of one xmm. vpackusdw twice packs four vectors into one
// (no saturation: every dword is below 65,536): lane i of the result holds, for each of the
// four, the two u16 sums of its qwords 2i and 2i + 1. Three packs per four vectors where
// shifts and ORs took five; the lanes are then folded in 256-bit steps and each direction's
// two u16 halves added by vpmaddwd.
inline __m128i sums_of_eight(const __m512i d[8]) {
  auto pack = [](const __m512i* q) {  // lane i: q[0]'s two sums, then q[1]'s, q[2]'s, q[3]'s
    return _mm512_packus_epi32(_mm512_packus_epi32(q[0], q[1]), _mm512_packus_epi32(q[2], q[3]));
  };
  const __m512i p0 = pack(d), p1 = pack(d + 4);
  auto half = [](__m512i v) {
    return _mm256_add_epi16(_mm512_castsi512_si256(v), _mm512_extracti64x4_epi64(v, 1));
  };
  const __m256i a0 = half(p0), a1 = half(p1);
  const __m256i f = _mm256_add_epi16(_mm256_permute2x128_si256(a0, a1, 0x20),
                                     _mm256_permute2x128_si256(a0, a1, 0x31));
  const __m256i g = _mm256_madd_epi16(f, _mm256_set1_epi16(1));  // dword k: direction k's total
  return _mm_packus_epi32(_mm256_castsi256_si128(g), _mm256_extracti128_si256(g, 1));
}

// One column of one POI's window (8 bytes per row) against the block, for eight candidates
// dy' = 0..7: qword dy' of the result is the candidate's SAD. The column's window rows 1..8 are
// `top`, rows 9..16 `below` (row qwords, qword_rows); rows r + 1 .. r + 8 (valignq by r) against
// block row r broadcast give block row r's part of all eight candidates at once, so the eight
// parts add up in place, with no sum across a vector's qwords.
inline __m512i column_sads(Block prev, __m512i top, __m512i below) {
  auto part = [&](int r, __m512i rows) {
    const __m128i row =
        _mm_loadl_epi64(reinterpret_cast<const __m128i*>(prev.data + r * prev.stride));
    return _mm512_sad_epu8(rows, _mm512_broadcastq_epi64(row));
  };
  __m512i sum = part(0, top);
  [&]<int... R>(std::integer_sequence<int, R...>) {  // valignq's shift is an immediate
    ((sum = _mm512_add_epi64(sum, part(R + 1, _mm512_alignr_epi64(below, top, R + 1)))), ...);
  }
  (std::make_integer_sequence<int, 7>{});
  return sum;
}

// The sum of the eight qwords of v in qword 0 (each a psadbw's, <= 2,040: the total fits dword
// 0; pair_column's hold two such in their dwords, whose totals the 64-bit adds keep apart), left
// in a vector register: a trip through a general register costs the key's latency.
inline __m128i qword_total(__m512i v) {
  const __m256i h = _mm256_add_epi64(_mm512_castsi512_si256(v), _mm512_extracti64x4_epi64(v, 1));
  const __m128i q = _mm_add_epi64(_mm256_castsi256_si128(h), _mm256_extracti128_si256(h, 1));
  return _mm_add_epi64(q, _mm_unpackhi_epi64(q, q));
}

// The last column alone, for 2S + 1 = 16k + 1 (S = 8, 16, 24): a 16-dx' chunk for one dx' would
// spend as many vdbpsadbw as a full one. Instead the column (dx' = 2S) is column_sads per eight
// candidates, dy' = 8m .. 8m + 7 from the strip's parts m and m + 1 (window rows 1 + 8m ..
// 16 + 8m, window column 2S + 1), two such vectors keyed at once; the last candidate, dy' = 16k,
// is one psadbw of its eight rows (part 2k) against the block's rows, summed across the vector:
// its key is returned (in every dword of an xmm), for the caller's reduction to take after its
// first steps, so that this chain's end does not wait for them.
__m128i search_last_column(Block prev, Window next, int radius, Keys& best) {
  asm("" : "+r"(prev.data));  // the block rows loaded again, as in pair_column
  const int side = 2 * radius + 1;
  const int halves = side / 8;  // 2k vectors of eight candidates, then dy' = 16k
  const std::uint8_t* strip = next.data + 1 + 2 * radius;
  auto strip_part = [&](int m) {  // window rows 1 + 8m .. 8 + 8m (2S + 8 rows in all)
    return qword_rows(strip + (1 + 8 * m) * next.stride, next.stride);
  };
  // Dword i of a key vector: qword i of the first eight candidates, then of the next eight.
  const __m512i pick = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
  const __m512i rows = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  __m512i part = strip_part(0);
  for (int m = 0; m < halves; m += 2) {
    const __m512i mid = strip_part(m + 1), next_part = strip_part(m + 2);
    const __m512i sads = _mm512_permutex2var_epi32(column_sads(prev, part, mid), pick,
                                                   column_sads(prev, mid, next_part));
    const __m512i dy = _mm512_add_epi32(rows, _mm512_set1_epi32(8 * m));
    const __m512i position =
        _mm512_add_epi32(_mm512_slli_epi32(dy, 6), _mm512_set1_epi32(2 * radius));
    best.even = _mm512_min_epu32(best.even,
                                 _mm512_or_si512(_mm512_slli_epi32(sads, kPositionBits), position));
    part = next_part;
  }
  const __m128i last = qword_total(_mm512_sad_epu8(part, qword_rows(prev.data, prev.stride)));
  const __m128i key = _mm_or_si128(_mm_slli_epi32(last, kPositionBits),
                                   _mm_cvtsi32_si128((side - 1) * kRowPositions + 2 * radius));
  return _mm_shuffle_epi32(key, 0);
}

inline __m512i merged_keys(const Keys& best) { return _mm512_min_epu32(best.even, best.odd); }

inline BlockMatch match_of(std::uint32_t key, int radius) {
  const std::uint32_t position = key & ((1u << kPositionBits) - 1);
  return {static_cast<int>(position % kRowPositions) - radius,
          static_cast<int>(position / kRowPositions) - radius, key >> kPositionBits};
}

// match_of for a BlockMatch returned in registers (rax = dx | dy << 32, rdx = sad): dx and dy put
// together in one 64-bit value first. From the struct GCC 12 built rax by two 32-bit stores and
// a 64-bit load, a store forward that fails, at the end of every search_at call.
inline BlockMatch returned_match(std::uint32_t key, int radius) {
  const BlockMatch m = match_of(key, radius);
  const std::uint64_t dx_dy = static_cast<std::uint32_t>(m.dx) |
                              static_cast<std::uint64_t>(static_cast<std::uint32_t>(m.dy)) << 32;
  BlockMatch r;
  static_assert(offsetof(BlockMatch, dy) == sizeof(int));
  __builtin_memcpy(static_cast<void*>(&r), &dx_dy, sizeof dx_dy);
  r.sad = m.sad;
  return r;
}

// kRadius: S fixed at compile time (see key_rows), or 0 for any S.
template <int kRadius>
BlockMatch search_at(Block prev, Window next, int radius) {
  const int S = kRadius > 0 ? kRadius : radius;
  const __m512i halves = _mm512_setr_epi32(0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1);
  __m512i block[8];
  for (int r = 0; r < 8; ++r) {
    const __m128i row =
        _mm_loadl_epi64(reinterpret_cast<const __m128i*>(prev.data + r * prev.stride));
    block[r] = _mm512_permutexvar_epi32(halves, _mm512_zextsi128_si512(row));
  }
  Keys best;
  const bool column = (2 * S + 1) % 16 == 1;
  const int chunks = chunks_of_16(S) - (column ? 1 : 0);
  for (int c = 0; c < chunks; ++c) {
    const int last_dx = (2 * S - 16 * c < 15) ? 2 * S - 16 * c : 15;
    const RowLoader loader{next.data + 1 + 16 * c, next.stride, (1ull << (last_dx + 8)) - 1,
                           _mm512_setr_epi32(0, 1, 2, 3, 2, 3, 4, 5, 1, 2, 3, 4, 3, 4, 5, 6)};
    search_chunk<kRadius>(block, loader, S, c, best);
  }
  __m128i last = _mm_set1_epi32(-1);
  if (column) last = search_last_column(prev, next, S, best);
  const __m512i keys = merged_keys(best);
  const __m256i half =
      _mm256_min_epu32(_mm512_castsi512_si256(keys), _mm512_extracti64x4_epi64(keys, 1));
  __m128i q = _mm_min_epu32(
      _mm_min_epu32(_mm256_castsi256_si128(half), _mm256_extracti128_si256(half, 1)), last);
  q = _mm_min_epu32(q, _mm_shuffle_epi32(q, _MM_SHUFFLE(1, 0, 3, 2)));
  q = _mm_min_epu32(q, _mm_shuffle_epi32(q, _MM_SHUFFLE(2, 3, 0, 1)));
  const auto key = static_cast<std::uint32_t>(_mm_cvtsi128_si32(q));
  _mm256_zeroupper();
  return returned_match(key, S);
}

// The radii of the profiles and of the bench's default sweep get a search compiled for them.
BlockMatch search(Block prev, Window next, int radius, OpCounts*) {
  switch (radius) {
    case 4:
      return search_at<4>(prev, next, radius);
    case 7:
      return search_at<7>(prev, next, radius);
    case 8:
      return search_at<8>(prev, next, radius);
    case 12:
      return search_at<12>(prev, next, radius);
    case 16:
      return search_at<16>(prev, next, radius);
    default:
      return search_at<0>(prev, next, radius);
  }
}

constexpr int kPairMaxRadius = 4;  // 2S + 1 <= 9: dx' 0..7 in the lanes, dx' = 8 by the column

// The keys of the column's candidates dy' = 0..7 of a and b in key_rows' pair layout (a in
// lanes 0 and 2, b in lanes 1 and 3; dy' = i + 4 (lane / 2) in dword i of a lane), and the keys
// of the last candidates (dx', dy') = (8, 8) of a and b, each one psadbw of its rows 9..16, in
// dwords 0 (a) and 1 (b) of an xmm.
struct PairColumn {
  __m512i keys;
  __m128i last;
};

PairColumn pair_column(Block prev_a, Window next_a, Block prev_b, Window next_b) {
  // The block rows are loaded again here, not kept from the search's loads: GCC would keep
  // those 16 xmm for the column and spill them, each store then reloaded on the way to the
  // block's vpermt2d. An empty asm hides that the pointers are the same.
  asm("" : "+r"(prev_a.data), "+r"(prev_b.data));
  // Window column 9, rows 1..8 and 9..16 (the latter also the last candidates' rows).
  auto column = [](Window w, int row) { return qword_rows(w.data + 9 + row * w.stride, w.stride); };
  const __m512i strip_a = column(next_a, 9), strip_b = column(next_b, 9);
  const __m512i sads_a = column_sads(prev_a, column(next_a, 1), strip_a);
  const __m512i sads_b = column_sads(prev_b, column(next_b, 1), strip_b);
  const __m512i pick = _mm512_setr_epi32(0, 2, 4, 6, 16, 18, 20, 22, 8, 10, 12, 14, 24, 26, 28, 30);
  const __m512i position = _mm512_setr_epi32(8, 72, 136, 200, 8, 72, 136, 200, 264, 328, 392, 456,
                                             264, 328, 392, 456);  // dy' * 64 + 8
  PairColumn c;
  c.keys = _mm512_or_si512(
      _mm512_slli_epi32(_mm512_permutex2var_epi32(sads_a, pick, sads_b), kPositionBits), position);
  // a's eight row SADs in the low dwords, b's in the high ones (each <= 2,040: no carry).
  const __m512i last = _mm512_or_si512(
      _mm512_sad_epu8(strip_a, qword_rows(prev_a.data, prev_a.stride)),
      _mm512_slli_epi64(_mm512_sad_epu8(strip_b, qword_rows(prev_b.data, prev_b.stride)), 32));
  c.last = _mm_or_si128(_mm_slli_epi32(qword_total(last), kPositionBits),
                        _mm_set1_epi32(8 * kRowPositions + 8));
  return c;
}

// The searches of two POIs a and b (one grid row, one frame pair) at once, S <= kPairMaxRadius;
// `out` gets a's match, then b's, each what search() gives for it alone.
template <int S>
void search_pair_at(Block prev_a, Window next_a, Block prev_b, Window next_b, BlockMatch out[2]) {
  // Block row r as dwords: a's columns 0..3 in lane 0, 4..7 in lane 1, b's in lanes 2 and 3.
  const __m512i halves = _mm512_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1, 16, 16, 16, 16, 17, 17, 17, 17);
  __m512i block[8];
  for (int r = 0; r < 8; ++r) {
    const __m128i ra =
        _mm_loadl_epi64(reinterpret_cast<const __m128i*>(prev_a.data + r * prev_a.stride));
    const __m128i rb =
        _mm_loadl_epi64(reinterpret_cast<const __m128i*>(prev_b.data + r * prev_b.stride));
    block[r] =
        _mm512_permutex2var_epi32(_mm512_zextsi128_si512(ra), halves, _mm512_zextsi128_si512(rb));
  }
  const int last_dx = 2 * S < 7 ? 2 * S : 7;
  const PairLoader loader{next_a.data + 1, next_b.data + 1, next_a.stride,
                          (1ull << (last_dx + 8)) - 1, 1 + 16 <= row_bytes(S)};
  // H = [a of dy' | b of dy' | a of dy' + 1 | b of dy' + 1]: lanes 0 + 1 and 2 + 3 of each row.
  const __m512i position =
      _mm512_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6, kRowPositions + 0, kRowPositions + 2,
                        kRowPositions + 4, kRowPositions + 6, kRowPositions + 0, kRowPositions + 2,
                        kRowPositions + 4, kRowPositions + 6);
  const DxMasks ok = dx_masks(2 * S + 1, 0, 1);
  // dx' = 8 first: the column's chain of loads, psadbw and reductions then runs beside the rows'
  // vdbpsadbw instead of after them, where the call's end waited for it.
  Keys best;
  __m128i last = _mm_set1_epi32(-1);
  if (2 * S + 1 > 8) {
    const PairColumn column = pair_column(prev_a, next_a, prev_b, next_b);
    best.even = column.keys;
    last = column.last;
  }
  key_rows<PairLoader, 0x88, 0xDD, S>(block, loader, S, position, ok.even, ok.odd, best);
  const __m512i keys = merged_keys(best);
  // Both POIs' minima at once: a's lanes 0 and 2 folded onto b's 1 and 3, the two 128-bit lanes
  // interleaved by dword (a, b, a, b), then their qwords: dword 0 holds a's key, dword 1 b's.
  const __m256i lanes =
      _mm256_min_epu32(_mm512_castsi512_si256(keys), _mm512_extracti64x4_epi64(keys, 1));
  const __m128i lo = _mm256_castsi256_si128(lanes), hi = _mm256_extracti128_si256(lanes, 1);
  __m128i ab = _mm_min_epu32(_mm_unpacklo_epi32(lo, hi), _mm_unpackhi_epi32(lo, hi));
  ab = _mm_min_epu32(_mm_min_epu32(ab, _mm_shuffle_epi32(ab, _MM_SHUFFLE(1, 0, 3, 2))), last);
  const auto both = static_cast<std::uint64_t>(_mm_cvtsi128_si64(ab));
  _mm256_zeroupper();
  out[0] = match_of(static_cast<std::uint32_t>(both), S);
  out[1] = match_of(static_cast<std::uint32_t>(both >> 32), S);
}

void search_pair(Block prev_a, Window next_a, Block prev_b, Window next_b, int radius,
                 BlockMatch out[2]) {
  switch (radius) {
    case 1:
      return search_pair_at<1>(prev_a, next_a, prev_b, next_b, out);
    case 2:
      return search_pair_at<2>(prev_a, next_a, prev_b, next_b, out);
    case 3:
      return search_pair_at<3>(prev_a, next_a, prev_b, next_b, out);
    default:  // kPairMaxRadius
      return search_pair_at<kPairMaxRadius>(prev_a, next_a, prev_b, next_b, out);
  }
}

// SPEC §3 step 3 with the eight block rows as the eight qwords of a zmm: psadbw then gives one
// direction's eight row SADs at once. For each column offset u = -1, 0, +1 the rows -1..6 and
// 7..8 are loaded once, complemented so that pavgb floors (see x86_half_pixel.hpp), and the
// rows starting at 0 and at +1 are the same data moved down one or two qwords (valignq), after
// the horizontal averages. The eight direction sums are reduced together (sums_of_eight) into
// the u16 lanes of one xmm.
[[gnu::always_inline]] inline __m128i half_pixel_sums(Block prev, const std::uint8_t* around,
                                                      std::ptrdiff_t stride) {
  const __m512i ones = _mm512_set1_epi8(-1);
  // Column s - 1: rows -1..6 in a zmm, rows 7..8 in an xmm (its two rows' work in 128-bit
  // operations, which cost Zen 4 half of a 512-bit one).
  __m512i top[3];
  __m128i low[3];
  for (int s = 0; s < 3; s += 2) {
    top[s] = _mm512_xor_si512(qword_rows(around + s, stride), ones);
    low[s] = _mm_xor_si128(two_rows(around + 8 * stride + s, stride), _mm512_castsi512_si128(ones));
  }
  // Columns 0..7 without loading them: columns -1..6 moved down a byte give 0..6, columns 1..8
  // moved up a byte give 1..7; the bytes both give are equal, and a shift brings in zeros, so
  // an OR of the two is columns 0..7 (complemented like the rest).
  top[1] = _mm512_or_si512(_mm512_srli_epi64(top[0], 8), _mm512_slli_epi64(top[2], 8));
  low[1] = _mm_or_si128(_mm_srli_epi64(low[0], 8), _mm_slli_epi64(low[2], 8));
  // Rows r + t (r = 0..7) of a plane given as its rows -1..6 and 7..8.
  auto down = [](__m512i lo8, __m128i hi2, int t) {
    const __m512i hi = _mm512_zextsi128_si512(hi2);
    return t == 0 ? _mm512_alignr_epi64(hi, lo8, 1) : _mm512_alignr_epi64(hi, lo8, 2);
  };
  const __m512i hl_top = _mm512_avg_epu8(top[0], top[1]), hr_top = _mm512_avg_epu8(top[1], top[2]);
  const __m128i hl_low = _mm_avg_epu8(low[0], low[1]), hr_low = _mm_avg_epu8(low[1], low[2]);
  const __m512i p_up = top[1], p_mid = down(top[1], low[1], 0), p_down = down(top[1], low[1], 1);
  const __m512i hl_up = hl_top, hl = down(hl_top, hl_low, 0), hl_down = down(hl_top, hl_low, 1);
  const __m512i hr_up = hr_top, hr = down(hr_top, hr_low, 0), hr_down = down(hr_top, hr_low, 1);
  const __m512i q = _mm512_xor_si512(qword_rows(prev.data, prev.stride), ones);
  const __m512i s[8] = {_mm512_sad_epu8(hr, q),                              // k0 h(c, r)
                        _mm512_sad_epu8(_mm512_avg_epu8(hr, hr_down), q),    // k1 d(c, r)
                        _mm512_sad_epu8(_mm512_avg_epu8(p_mid, p_down), q),  // k2 g(c, r)
                        _mm512_sad_epu8(_mm512_avg_epu8(hl, hl_down), q),    // k3 d(c-1, r)
                        _mm512_sad_epu8(hl, q),                              // k4 h(c-1, r)
                        _mm512_sad_epu8(_mm512_avg_epu8(hl_up, hl), q),      // k5 d(c-1, r-1)
                        _mm512_sad_epu8(_mm512_avg_epu8(p_up, p_mid), q),    // k6 g(c, r-1)
                        _mm512_sad_epu8(_mm512_avg_epu8(hr_up, hr), q)};     // k7 d(c, r-1)
  return sums_of_eight(s);
}

// Step 3 and its vote without a branch on the SADs: phminposuw gives the smallest of the eight
// u16 sums and the lowest k that holds it, i.e. the first minimum over k = 0..7, which wins
// only when strictly below the integer match's SAD (ties keep the match or the lower k, as in
// ref::select_half_pixel).
int half_pixel_vote(Block prev, const std::uint8_t* around, std::ptrdiff_t stride,
                    std::uint32_t sad, std::uint16_t sub[8]) {
  const __m128i sums = half_pixel_sums(prev, around, stride);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(sub), sums);
  const auto least = static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_minpos_epu16(sums)));
  _mm256_zeroupper();
  return (least & 0xFFFFu) < sad ? static_cast<int>(least >> 16) : kDirNone;
}

}  // namespace

const IsaKernel& avx512bw_kernel() {
  static const IsaKernel k{"avx512bw", row_bytes,   feature_sse2,   search,         nullptr,
                           false,      search_pair, kPairMaxRadius, half_pixel_vote};
  return k;
}

}  // namespace pxflow::cpu
