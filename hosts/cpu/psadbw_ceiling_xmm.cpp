// psadbw ceiling, 16 bytes per instruction: 12 independent chains x[i] = psadbw(x[i], row i),
// the row loaded from L1 every time; 12 chains cover the 3-cycle latency several times over, so
// only psadbw throughput limits the loop.
#include <emmintrin.h>

#include "psadbw_ceiling.hpp"

namespace pxflow::cpu {

std::uint64_t psadbw_xmm(const std::uint8_t* data, std::int64_t rounds) {
  __m128i x[12];
  for (int i = 0; i < 12; ++i)
    x[i] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(data + 64 * i));
  for (std::int64_t n = 0; n < rounds; ++n) {
    asm volatile("" : "+r"(data));  // reload the rows, only they (psadbw_ceiling.hpp)
    for (int i = 0; i < 12; ++i) {
      const __m128i row = _mm_loadu_si128(reinterpret_cast<const __m128i*>(data + 64 * i));
      x[i] = _mm_sad_epu8(x[i], row);
    }
  }
  std::uint64_t sum = 0;
  for (int i = 0; i < 12; ++i) sum += static_cast<std::uint64_t>(_mm_cvtsi128_si64(x[i]));
  return sum;
}

}  // namespace pxflow::cpu
