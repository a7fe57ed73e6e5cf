// SAD ceilings at 256 bits: 12 independent chains x[i] = op(x[i], row i), the row loaded from L1
// every time; 12 chains cover the instructions' latency several times over, so only their
// throughput limits the loop. psadbw compares 32 bytes per instruction, vmpsadbw 64 (16 SADs of
// 4-byte groups: avx2.cpp's search instruction).
#include <immintrin.h>

#include "psadbw_ceiling.hpp"

namespace pxflow::cpu {
namespace {

template <typename Op>
std::uint64_t chains(const std::uint8_t* data, std::int64_t rounds, Op op) {
  __m256i x[12];
  for (int i = 0; i < 12; ++i)
    x[i] = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(data + 64 * i));
  for (std::int64_t n = 0; n < rounds; ++n) {
    asm volatile("" : "+r"(data));  // reload the rows, only they (psadbw_ceiling.hpp)
    for (int i = 0; i < 12; ++i) {
      const __m256i row = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(data + 64 * i));
      x[i] = op(x[i], row);
    }
  }
  std::uint64_t sum = 0;
  for (int i = 0; i < 12; ++i) sum += static_cast<std::uint64_t>(_mm256_extract_epi64(x[i], 0));
  return sum;
}

}  // namespace

std::uint64_t psadbw_ymm(const std::uint8_t* data, std::int64_t rounds) {
  return chains(data, rounds, [](__m256i a, __m256i b) { return _mm256_sad_epu8(a, b); });
}

std::uint64_t vmpsadbw_ymm(const std::uint8_t* data, std::int64_t rounds) {
  return chains(data, rounds, [](__m256i a, __m256i b) { return _mm256_mpsadbw_epu8(a, b, 0); });
}

}  // namespace pxflow::cpu
