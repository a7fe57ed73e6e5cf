// swar: the 4-byte SIMD-within-a-register kernel, written with the firmware's vocabulary
// (USAD8 / USADA8 / UHADD8 of reference/primitives.hpp) and in its shape: the 8x8 block is 16
// words, two 4-byte halves per row. It is the template for any 32-bit MCU without SIMD and the C
// model of the GAP8 kernel, so it counts every 4-byte operation it performs: per POI 6 for the
// feature test, 16 per integer candidate and 16 per half-pixel direction (91,520 per px4flow-64
// frame in which all 64 POIs pass).
#include "cpu_kernel.hpp"
#include "primitives.hpp"

namespace pxflow::cpu {
namespace {

int row_bytes(int radius) { return 2 * radius + 10; }  // exact: every load is a needed word

struct BlockWords {
  std::uint32_t w[16];  // row r: w[2r] = columns 0..3, w[2r+1] = columns 4..7
};

BlockWords block_words(Block prev) {
  BlockWords b;
  for (int r = 0; r < 8; ++r) {
    b.w[2 * r] = load4(prev.data + r * prev.stride);
    b.w[2 * r + 1] = load4(prev.data + r * prev.stride + 4);
  }
  return b;
}

// The firmware's inner loop: 16 USADA8 of block words against the candidate's words.
template <class Word>
std::uint32_t block_sad(const BlockWords& b, Word&& word) {
  std::uint32_t acc = 0;
  for (int r = 0; r < 8; ++r) {
    acc = usada8(b.w[2 * r], word(r, 0), acc);
    acc = usada8(b.w[2 * r + 1], word(r, 4), acc);
  }
  return acc;
}

BlockMatch search(Block prev, Window next, int radius, OpCounts* counts) {
  const int S = radius;
  const BlockWords b = block_words(prev);
  BlockMatch best{0, 0, 0xFFFFFFFFu};  // SPEC §3 sentinel
  for (int dy = -S; dy <= S; ++dy) {
    for (int dx = -S; dx <= S; ++dx) {
      const std::uint8_t* cand = next.data + (dy + S + 1) * next.stride + (dx + S + 1);
      const std::uint32_t sad =
          block_sad(b, [&](int r, int c) { return load4(cand + r * next.stride + c); });
      if (sad < best.sad) best = {dx, dy, sad};  // strict: ties keep the raster-order first
    }
  }
  if (counts) counts->sad_ops += static_cast<std::uint64_t>(2 * S + 1) * (2 * S + 1) * 16;
  return best;
}

void half_pixel(Block prev, const std::uint8_t* around, std::ptrdiff_t stride, std::uint32_t sub[8],
                OpCounts* counts) {
  // P(u, v) as words of four pixels starting at column u.
  auto P = [&](int u, int v) { return load4(around + (v + 1) * stride + (u + 1)); };
  auto h = [&](int u, int v) { return uhadd8(P(u, v), P(u + 1, v)); };
  auto g = [&](int u, int v) { return uhadd8(P(u, v), P(u, v + 1)); };
  // The diagonal averages two horizontal averages, each floored (SPEC §3).
  auto d = [&](int u, int v) { return uhadd8(h(u, v), h(u, v + 1)); };
  const BlockWords b = block_words(prev);
  sub[0] = block_sad(b, [&](int r, int c) { return h(c, r); });
  sub[1] = block_sad(b, [&](int r, int c) { return d(c, r); });
  sub[2] = block_sad(b, [&](int r, int c) { return g(c, r); });
  sub[3] = block_sad(b, [&](int r, int c) { return d(c - 1, r); });
  sub[4] = block_sad(b, [&](int r, int c) { return h(c - 1, r); });
  sub[5] = block_sad(b, [&](int r, int c) { return d(c - 1, r - 1); });
  sub[6] = block_sad(b, [&](int r, int c) { return g(c, r - 1); });
  sub[7] = block_sad(b, [&](int r, int c) { return d(c, r - 1); });
  if (counts) {
    counts->sad_ops += 8 * 16;
    counts->interpolations += 4 * 64 + 4 * 128;  // as ref-original: a diagonal value costs 2
  }
}

}  // namespace

const IsaKernel& swar_kernel() {
  static const IsaKernel k{"swar", row_bytes, nullptr, search, half_pixel, true};
  return k;
}

}  // namespace pxflow::cpu
