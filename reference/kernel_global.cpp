// ref-global: the three half-pixel planes h, g, d of the whole `next` frame are computed once,
// before any matching (W*H*3 interpolations per pair, the paper's count, whether or not a POI is
// accepted); the POIs then only read them. Cells in the last column or row would need a pixel
// beyond the frame: their reads are clamped, and no POI ever reads those cells (SPEC §3: every
// value a POI needs lies inside the frame).
#include <algorithm>
#include <vector>

#include "kernel_variants.hpp"
#include "poi_steps.hpp"

namespace pxflow::ref {

void run_global(const FramePair& f, const Params& p, std::span<PoiRecord> out, OpCounts& cnt) {
  const int W = f.next.width;
  const int H = f.next.height;
  const std::size_t n = static_cast<std::size_t>(W) * H;
  std::vector<std::uint8_t> hp(n), gp(n), dp(n);
  auto N = [&](int x, int y) { return f.next.at(std::min(x, W - 1), std::min(y, H - 1)); };
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      hp[y * W + x] = avg_floor(N(x, y), N(x + 1, y));
      gp[y * W + x] = avg_floor(N(x, y), N(x, y + 1));
    }
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      dp[y * W + x] = avg_floor(hp[y * W + x], hp[std::min(y + 1, H - 1) * W + x]);
  cnt.interpolations += 3 * n;

  run_pois(f, p, out, cnt, [&](const Poi& poi, const Match& m, std::uint32_t sub[8]) {
    const int x0 = poi.x + m.bx;
    const int y0 = poi.y + m.by;
    auto h = [&](int u, int v) { return hp[(y0 + v) * W + x0 + u]; };
    auto g = [&](int u, int v) { return gp[(y0 + v) * W + x0 + u]; };
    auto d = [&](int u, int v) { return dp[(y0 + v) * W + x0 + u]; };
    for (int k = 0; k < 8; ++k)
      sub[k] = block_sad(
          f.prev, poi.x, poi.y, [&](int c, int r) { return direction_value(k, c, r, h, g, d); },
          cnt);
  });
}

}  // namespace pxflow::ref
