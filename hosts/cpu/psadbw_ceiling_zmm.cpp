// SAD ceilings at 512 bits: 12 independent chains x[i] = op(x[i], row i), the row loaded from L1
// every time; 12 chains cover the instructions' latency several times over, so only their
// throughput limits the loop. psadbw compares 64 bytes per instruction, vdbpsadbw 128 (32 SADs of
// 4-byte groups: avx512bw.cpp's search instruction).
#include <immintrin.h>

#include "psadbw_ceiling.hpp"

namespace pxflow::cpu {
namespace {

template <typename Op>
std::uint64_t chains(const std::uint8_t* data, std::int64_t rounds, Op op) {
  __m512i x[12];
  for (int i = 0; i < 12; ++i)
    x[i] = _mm512_loadu_si512(reinterpret_cast<const __m512i*>(data + 64 * i));
  for (std::int64_t n = 0; n < rounds; ++n) {
    asm volatile("" : "+r"(data));  // reload the rows, only they (psadbw_ceiling.hpp)
    for (int i = 0; i < 12; ++i) {
      const __m512i row = _mm512_loadu_si512(reinterpret_cast<const __m512i*>(data + 64 * i));
      x[i] = op(x[i], row);
    }
  }
  std::uint64_t sum = 0;
  for (int i = 0; i < 12; ++i) {
    alignas(64) std::uint64_t lanes[8];
    _mm512_store_si512(lanes, x[i]);
    sum += lanes[0];
  }
  return sum;
}

}  // namespace

std::uint64_t psadbw_zmm(const std::uint8_t* data, std::int64_t rounds) {
  return chains(data, rounds, [](__m512i a, __m512i b) { return _mm512_sad_epu8(a, b); });
}

std::uint64_t vdbpsadbw_zmm(const std::uint8_t* data, std::int64_t rounds) {
  return chains(data, rounds, [](__m512i a, __m512i b) { return _mm512_dbsad_epu8(a, b, 0x94); });
}

}  // namespace pxflow::cpu
