// ref-local: per accepted POI, the three half-pixel planes h, g, d over the matched block plus
// a one-pixel border (10x10 each, block coordinates -1..8) are computed once, then all eight
// directions read them. Charged 300 interpolations per accepted POI, the paper's count; only 243
// of those values are ever read. The plane cells on the far border (u = 8 or v = 8) would need
// pixel 9 of the window: their reads are clamped to the window, and no direction reads them.
#include <algorithm>

#include "kernel_variants.hpp"
#include "poi_steps.hpp"

namespace pxflow::ref {
namespace {

constexpr int kSide = 10;  // -1..8
struct Planes {
  std::uint8_t h[kSide][kSide], g[kSide][kSide], d[kSide][kSide];  // [v+1][u+1]
};

}  // namespace

void run_local(const FramePair& f, const Params& p, std::span<PoiRecord> out, OpCounts& cnt) {
  run_pois(f, p, out, cnt, [&](const Poi& poi, const Match& m, std::uint32_t sub[8]) {
    const int x0 = poi.x + m.bx;
    const int y0 = poi.y + m.by;
    auto P = [&](int u, int v) { return f.next.at(x0 + std::min(u, 8), y0 + std::min(v, 8)); };
    Planes pl;
    for (int v = -1; v <= 8; ++v)
      for (int u = -1; u <= 8; ++u) {
        pl.h[v + 1][u + 1] = avg_floor(P(u, v), P(u + 1, v));
        pl.g[v + 1][u + 1] = avg_floor(P(u, v), P(u, v + 1));
      }
    for (int v = -1; v <= 8; ++v)
      for (int u = -1; u <= 8; ++u)
        pl.d[v + 1][u + 1] = avg_floor(pl.h[v + 1][u + 1], pl.h[std::min(v + 1, 8) + 1][u + 1]);
    cnt.interpolations += 3 * kSide * kSide;

    auto h = [&](int u, int v) { return pl.h[v + 1][u + 1]; };
    auto g = [&](int u, int v) { return pl.g[v + 1][u + 1]; };
    auto d = [&](int u, int v) { return pl.d[v + 1][u + 1]; };
    for (int k = 0; k < 8; ++k)
      sub[k] = block_sad(
          f.prev, poi.x, poi.y, [&](int c, int r) { return direction_value(k, c, r, h, g, d); },
          cnt);
  });
}

}  // namespace pxflow::ref
