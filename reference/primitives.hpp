// The 4-byte SIMD vocabulary of the firmware (SPEC §7), in portable C++. The reference kernel
// works pixel by pixel but charges its work in these units; the SWAR and GAP8 kernels use them.
#pragma once
#include <cstdint>
#include <cstring>

namespace pxflow {

// Four consecutive bytes as one word. Byte order does not matter: every lane is independent.
inline std::uint32_t load4(const std::uint8_t* p) {
  std::uint32_t w;
  std::memcpy(&w, p, 4);
  return w;
}

// Sum over the four bytes of |a_i - b_i|, 0..1020 (ARM USAD8).
inline std::uint32_t usad8(std::uint32_t a, std::uint32_t b) {
  std::uint32_t sum = 0;
  for (int s = 0; s < 32; s += 8) {
    const int x = static_cast<int>((a >> s) & 0xFF) - static_cast<int>((b >> s) & 0xFF);
    sum += static_cast<std::uint32_t>(x < 0 ? -x : x);
  }
  return sum;
}

// acc + USAD8(a, b), wrapping mod 2^32 like the instruction (ARM USADA8).
inline std::uint32_t usada8(std::uint32_t a, std::uint32_t b, std::uint32_t acc) {
  return acc + usad8(a, b);
}

// Per byte floor((a_i + b_i) / 2) (ARM UHADD8). The carry-free form: the common bits plus half
// of the differing bits, with each lane's low bit masked so it cannot leak into its neighbour.
// NOT x86 pavgb / OpenCL rhadd / GLSL (a+b+1)/2: those round up.
inline std::uint32_t uhadd8(std::uint32_t a, std::uint32_t b) {
  return (a & b) + (((a ^ b) & 0xFEFEFEFEu) >> 1);
}

// One lane of uhadd8: the floor average every half-pixel value is made of.
inline std::uint8_t avg_floor(std::uint8_t a, std::uint8_t b) {
  return static_cast<std::uint8_t>((a + b) >> 1);
}

}  // namespace pxflow
