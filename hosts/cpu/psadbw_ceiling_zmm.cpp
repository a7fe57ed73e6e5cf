// psadbw ceiling, 64 bytes per instruction: 12 independent chains x[i] = psadbw(x[i], row i),
// the row loaded from L1 every time; 12 chains cover the 3-cycle latency several times over, so
// only psadbw throughput limits the loop.
#include <immintrin.h>

#include "psadbw_ceiling.hpp"

namespace pxflow::cpu {

std::uint64_t psadbw_zmm(const std::uint8_t* data, std::int64_t rounds) {
  __m512i x[12];
  for (int i = 0; i < 12; ++i)
    x[i] = _mm512_loadu_si512(reinterpret_cast<const __m512i*>(data + 64 * i));
  for (std::int64_t n = 0; n < rounds; ++n) {
    for (int i = 0; i < 12; ++i) {
      const __m512i row = _mm512_loadu_si512(reinterpret_cast<const __m512i*>(data + 64 * i));
      asm volatile("" : "+v"(x[i]) : : "memory");  // reload the row every round
      x[i] = _mm512_sad_epu8(x[i], row);
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

}  // namespace pxflow::cpu
