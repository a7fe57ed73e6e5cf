// The fast variant's estimate in integers (kernels/gap8/fast_float.h) gives the IEEE bits of the
// spec core's float steps (spec/include/pxflow_spec/estimate.h), here computed by the host's
// float arithmetic: exhaustively for up to 64 accepted POIs (every bin sum and every S), and on
// random draws up to the 2047 POIs the kernel's L1 can hold.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <random>

#include "fast_float.h"

namespace pxflow::test {
namespace {

std::uint32_t bits_of(float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// SPEC §5, HF on: (V / Wt - (2S+1)) / 2 in float, one rounding per operation.
std::uint32_t filtered_reference(std::uint32_t value, std::uint32_t weight, std::uint32_t k) {
  return bits_of(((float)value / (float)weight - (float)k) / 2.0f);
}

// SPEC §5, HF off: ((float)sum / 2) / count.
std::uint32_t mean_reference(std::int32_t sum, std::uint32_t count) {
  return bits_of(((float)sum / 2.0f) / (float)count);
}

}  // namespace

TEST_CASE("gap8 fast estimate: integer float steps are the spec's bits", "[gap8]") {
  std::uint64_t checked = 0;
  for (std::uint32_t weight = 1; weight <= 64; ++weight)
    for (std::uint32_t value = 0; value <= 126 * weight; ++value)
      for (std::uint32_t k = 3; k <= 63; k += 2) {
        const std::uint32_t got = fast_filtered_bits(value, weight, k);
        if (got != filtered_reference(value, weight, k))
          FAIL("V " << value << " Wt " << weight << " k " << k << ": " << got);
        ++checked;
      }
  for (std::uint32_t count = 1; count <= 64; ++count)
    for (std::int32_t sum = -63 * (std::int32_t)count; sum <= 63 * (std::int32_t)count; ++sum) {
      if (fast_mean_bits(sum, count) != mean_reference(sum, count))
        FAIL("sum " << sum << " count " << count);
      ++checked;
    }
  std::mt19937 rng(2029);
  for (int n = 0; n < 2000000; ++n) {
    const std::uint32_t weight = 1 + rng() % 2047, k = 3 + 2 * (rng() % 31);
    const std::uint32_t value = rng() % (126 * weight + 1);
    REQUIRE(fast_filtered_bits(value, weight, k) == filtered_reference(value, weight, k));
    const std::int32_t sum = (std::int32_t)(rng() % (127 * weight)) - 63 * (std::int32_t)weight;
    REQUIRE(fast_mean_bits(sum, weight) == mean_reference(sum, weight));
  }
  CHECK(checked > 8000000);
}

}  // namespace pxflow::test
