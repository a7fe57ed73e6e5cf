// neon: AArch64 Advanced SIMD. vabal_u8 accumulates the absolute differences of 8 pixels into
// 8 u16 lanes, so a candidate is 8 vabal and one vaddvq; vhadd_u8 is the floor average of SPEC
// §7 (truncating halving add), no trick needed. Loads are 8 bytes of needed pixels only.
#include <arm_neon.h>

#include "cpu_kernel.hpp"

namespace pxflow::cpu {
namespace {

int row_bytes(int radius) { return 2 * radius + 10; }

BlockMatch search(Block prev, Window next, int radius, OpCounts*) {
  const int S = radius;
  uint8x8_t block[8];
  for (int r = 0; r < 8; ++r) block[r] = vld1_u8(prev.data + r * prev.stride);
  BlockMatch best{0, 0, 0xFFFFFFFFu};  // SPEC §3 sentinel
  for (int dy = -S; dy <= S; ++dy) {
    for (int dx = -S; dx <= S; ++dx) {
      const std::uint8_t* cand = next.data + (dy + S + 1) * next.stride + (dx + S + 1);
      uint16x8_t acc = vabdl_u8(block[0], vld1_u8(cand));
      for (int r = 1; r < 8; ++r) acc = vabal_u8(acc, block[r], vld1_u8(cand + r * next.stride));
      const std::uint32_t sad = vaddvq_u16(acc);  // <= 16,320: no u16 overflow
      if (sad < best.sad) best = {dx, dy, sad};   // strict: ties keep the raster-order first
    }
  }
  return best;
}

struct HalfRow {
  uint8x8_t p, h_left, h_right;  // P(c, v), h(c-1, v), h(c, v)
};

HalfRow half_row(const std::uint8_t* row_at_minus1) {
  const uint8x8_t left = vld1_u8(row_at_minus1);
  const uint8x8_t mid = vld1_u8(row_at_minus1 + 1);
  const uint8x8_t right = vld1_u8(row_at_minus1 + 2);
  return {mid, vhadd_u8(left, mid), vhadd_u8(mid, right)};
}

struct HalfPair {
  uint8x8_t g, d_left, d_right;  // g(c, v), d(c-1, v), d(c, v): diagonals from floored h
};

HalfPair half_pair(const HalfRow& upper, const HalfRow& lower) {
  return {vhadd_u8(upper.p, lower.p), vhadd_u8(upper.h_left, lower.h_left),
          vhadd_u8(upper.h_right, lower.h_right)};
}

void half_pixel(Block prev, const std::uint8_t* around, std::ptrdiff_t stride, std::uint32_t sub[8],
                OpCounts*) {
  uint16x8_t acc[8];
  for (auto& a : acc) a = vdupq_n_u16(0);
  HalfRow cur = half_row(around);  // row -1
  HalfPair above{};
  for (int v = 0; v <= 8; ++v) {
    const HalfRow next = half_row(around + (v + 1) * stride);
    const HalfPair below = half_pair(cur, next);  // rows (v-1, v)
    if (v >= 1) {                                 // finish row r = v-1
      const uint8x8_t q = vld1_u8(prev.data + (v - 1) * prev.stride);
      const uint8x8_t values[8] = {cur.h_right, below.d_right, below.g, below.d_left,
                                   cur.h_left,  above.d_left,  above.g, above.d_right};
      for (int k = 0; k < 8; ++k) acc[k] = vabal_u8(acc[k], q, values[k]);
    }
    above = below;
    cur = next;
  }
  for (int k = 0; k < 8; ++k) sub[k] = vaddvq_u16(acc[k]);
}

}  // namespace

const IsaKernel& neon_kernel() {
  static const IsaKernel k{"neon", row_bytes, nullptr, search, half_pixel, false};
  return k;
}

}  // namespace pxflow::cpu
