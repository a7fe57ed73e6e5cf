// The 4-byte primitives of SPEC §7, exhaustively per lane.
#include <catch2/catch.hpp>

#include "primitives.hpp"
#include "synthetic.hpp"

using namespace pxflow;

TEST_CASE("uhadd8 is the floor average in every lane, for every byte pair", "[primitives]") {
  for (std::uint32_t a = 0; a < 256; ++a)
    for (std::uint32_t b = 0; b < 256; ++b) {
      // Put the pair in all four lanes with different neighbours, so a carry leak would show.
      const std::uint32_t wa = a | (b << 8) | (a << 16) | (0xFFu << 24);
      const std::uint32_t wb = b | (a << 8) | (0xFFu << 16) | (b << 24);
      const std::uint32_t got = uhadd8(wa, wb);
      REQUIRE((got & 0xFF) == (a + b) / 2);
      REQUIRE(((got >> 8) & 0xFF) == (a + b) / 2);
      REQUIRE(((got >> 16) & 0xFF) == (a + 0xFF) / 2);
      REQUIRE((got >> 24) == (0xFF + b) / 2);
      REQUIRE(avg_floor(static_cast<std::uint8_t>(a), static_cast<std::uint8_t>(b)) == (a + b) / 2);
    }
  CHECK(uhadd8(0x00000001u, 0x00000002u) == 0x00000001u);  // round-up would give 2
  CHECK(uhadd8(0xFFFFFFFFu, 0xFFFFFFFFu) == 0xFFFFFFFFu);  // 9-bit intermediate, no overflow
}

TEST_CASE("usad8 sums four absolute differences: usada8 wraps mod 2^32", "[primitives]") {
  CHECK(usad8(0x00000000u, 0xFFFFFFFFu) == 1020);
  CHECK(usad8(0x01020304u, 0x04030201u) == 3 + 1 + 1 + 3);
  CHECK(usada8(0xFF00FF00u, 0x00FF00FFu, 0xFFFFFFFFu) == 1019);  // 2^32-1 + 1020 wraps
  Rng rng(5);
  for (int n = 0; n < 10000; ++n) {
    const auto a = static_cast<std::uint32_t>(rng.next()),
               b = static_cast<std::uint32_t>(rng.next());
    std::uint32_t expect = 0;
    for (int s = 0; s < 32; s += 8) {
      const int d = int((a >> s) & 0xFF) - int((b >> s) & 0xFF);
      expect += static_cast<std::uint32_t>(d < 0 ? -d : d);
    }
    REQUIRE(usad8(a, b) == expect);
    REQUIRE(usad8(a, b) == usad8(b, a));
  }
  const std::uint8_t bytes[5] = {1, 2, 3, 4, 5};
  CHECK(usad8(load4(bytes), load4(bytes + 1)) == 4);
}
