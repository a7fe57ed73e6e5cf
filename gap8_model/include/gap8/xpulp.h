// Semantics of the Xpulp instructions the model implements, as pure functions so they can be
// unit-tested against hand-computed results. Byte lanes are independent: lane i is bits 8i..8i+7.
#pragma once

#include <cstdint>

namespace gap8::xpulp {

inline uint32_t Lane(uint32_t x, int i) { return (x >> (8 * i)) & 0xFFu; }
inline int32_t SignedLane(uint32_t x, int i) { return static_cast<int8_t>(Lane(x, i)); }

// pv.*.sc.b: the scalar operand is rs2's low byte in every lane.
inline uint32_t SplatByte(uint32_t x) { return (x & 0xFFu) * 0x01010101u; }

template <typename F>
uint32_t PerByte(uint32_t a, uint32_t b, F f) {
  uint32_t r = 0;
  for (int i = 0; i < 4; ++i) r |= (static_cast<uint32_t>(f(a, b, i)) & 0xFFu) << (8 * i);
  return r;
}

inline uint32_t AddB(uint32_t a, uint32_t b) {
  return PerByte(a, b, [](uint32_t x, uint32_t y, int i) { return Lane(x, i) + Lane(y, i); });
}
inline uint32_t SubB(uint32_t a, uint32_t b) {
  return PerByte(a, b, [](uint32_t x, uint32_t y, int i) { return Lane(x, i) - Lane(y, i); });
}
// pv.avgu.b: per lane (uint8)(a_i + b_i) >> 1: the sum is taken in the 8-bit lane, so its
// carry is lost (GVSOC gvsoc-core models/cpu/iss/include/isa_lib/int.h, VEC_EXPR(AVGU, ...,
// ((uint8_t)(tmp_a[i] + tmp_b[i]) >> 1)); GreenWaves' builtins.h: "addition performed on 8
// bits"; pulp-platform/riscv-tests xpulp-dev pv_avgu: 0x8F75F8E9, 0xDD666F70 -> 0x366D332C).
// It is therefore NOT SPEC's floor average whenever a_i + b_i > 255.
inline uint32_t AvguB(uint32_t a, uint32_t b) {
  return PerByte(a, b, [](uint32_t x, uint32_t y, int i) {
    return static_cast<uint8_t>(Lane(x, i) + Lane(y, i)) >> 1;
  });
}
inline uint32_t MinuB(uint32_t a, uint32_t b) {
  return PerByte(a, b, [](uint32_t x, uint32_t y, int i) {
    return Lane(x, i) < Lane(y, i) ? Lane(x, i) : Lane(y, i);
  });
}
inline uint32_t MaxuB(uint32_t a, uint32_t b) {
  return PerByte(a, b, [](uint32_t x, uint32_t y, int i) {
    return Lane(x, i) > Lane(y, i) ? Lane(x, i) : Lane(y, i);
  });
}
// pv.abs.b: per signed byte; |-128| wraps to 0x80 as in the hardware's 8-bit result.
inline uint32_t AbsB(uint32_t a) {
  return PerByte(a, 0u, [](uint32_t x, uint32_t, int i) {
    int32_t v = SignedLane(x, i);
    return static_cast<uint32_t>(v < 0 ? -v : v);
  });
}
// pv.dotup.b: sum of unsigned x unsigned byte products.
inline uint32_t DotupB(uint32_t a, uint32_t b) {
  uint32_t s = 0;
  for (int i = 0; i < 4; ++i) s += Lane(a, i) * Lane(b, i);
  return s;
}
// pv.dotusp.b: sum of unsigned (rs1) x signed (rs2) byte products.
inline uint32_t DotuspB(uint32_t a, uint32_t b) {
  int32_t s = 0;
  for (int i = 0; i < 4; ++i) s += static_cast<int32_t>(Lane(a, i)) * SignedLane(b, i);
  return static_cast<uint32_t>(s);
}
// pv.sdot*: the dot product accumulated into rd, modulo 2^32.
inline uint32_t SdotupB(uint32_t acc, uint32_t a, uint32_t b) { return acc + DotupB(a, b); }
inline uint32_t SdotuspB(uint32_t acc, uint32_t a, uint32_t b) { return acc + DotuspB(a, b); }

inline uint32_t Abs(uint32_t a) {
  int32_t v = static_cast<int32_t>(a);
  return v < 0 ? 0u - a : a;  // p.abs of INT32_MIN stays INT32_MIN (two's complement wrap)
}
inline uint32_t Min(uint32_t a, uint32_t b) {
  return static_cast<int32_t>(a) < static_cast<int32_t>(b) ? a : b;
}
inline uint32_t Max(uint32_t a, uint32_t b) {
  return static_cast<int32_t>(a) > static_cast<int32_t>(b) ? a : b;
}
inline uint32_t Minu(uint32_t a, uint32_t b) { return a < b ? a : b; }
inline uint32_t Maxu(uint32_t a, uint32_t b) { return a > b ? a : b; }

}  // namespace gap8::xpulp
