// An independent reading of SPEC §3's half-pixel values, written straight from the table, with
// the wrong rules a port typically picks selectable. Tests use it to check the kernel's sub[]
// values and to prove that a test input tells the right rule from the wrong ones.
#pragma once
#include <cstdint>
#include <cstdlib>

#include "frame.hpp"

namespace pxflow::oracle {

enum class Rounding { kFloor, kRoundUp };
enum class Diagonal { kTwoHorizontalAverages, kFourPixelMean, kVerticalFirst };

struct Rules {
  Rounding rounding = Rounding::kFloor;
  Diagonal diagonal = Diagonal::kTwoHorizontalAverages;
};

inline int avg(int a, int b, Rounding r) {
  return r == Rounding::kFloor ? (a + b) / 2 : (a + b + 1) / 2;
}

// Value of block pixel (c, r) in direction k for a block matched at (x0, y0) of `next`.
inline int half_value(const FrameView& next, int x0, int y0, int k, int c, int r, Rules rules) {
  auto P = [&](int u, int v) { return int{next.at(x0 + u, y0 + v)}; };
  auto h = [&](int u, int v) { return avg(P(u, v), P(u + 1, v), rules.rounding); };
  auto g = [&](int u, int v) { return avg(P(u, v), P(u, v + 1), rules.rounding); };
  auto d = [&](int u, int v) {
    switch (rules.diagonal) {
      case Diagonal::kFourPixelMean:
        return (P(u, v) + P(u + 1, v) + P(u, v + 1) + P(u + 1, v + 1) + 2) / 4;
      case Diagonal::kVerticalFirst:
        return avg(g(u, v), g(u + 1, v), rules.rounding);
      default:
        return avg(h(u, v), h(u, v + 1), rules.rounding);
    }
  };
  switch (k) {
    case 0:
      return h(c, r);
    case 1:
      return d(c, r);
    case 2:
      return g(c, r);
    case 3:
      return d(c - 1, r);
    case 4:
      return h(c - 1, r);
    case 5:
      return d(c - 1, r - 1);
    case 6:
      return g(c, r - 1);
    default:
      return d(c, r - 1);
  }
}

// sub[k] of SPEC §3 for the POI at (i, j) matched at displacement (bx, by).
inline std::uint32_t half_sad(const FramePair& f, int i, int j, int bx, int by, int k,
                              Rules rules) {
  std::uint32_t sum = 0;
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 8; ++c)
      sum += static_cast<std::uint32_t>(std::abs(
          int{f.prev.at(i + c, j + r)} - half_value(f.next, i + bx, j + by, k, c, r, rules)));
  return sum;
}

}  // namespace pxflow::oracle
