// ref-original: the firmware's way. Every direction's values are interpolated from `next`
// pixel by pixel, so shared values are recomputed. Charged as the paper counts: one
// interpolation per horizontal or vertical value, two per diagonal (768 per accepted POI).
#include "kernel_variants.hpp"
#include "poi_steps.hpp"

namespace pxflow::ref {

void run_original(const FramePair& f, const Params& p, std::span<PoiRecord> out, OpCounts& cnt) {
  run_pois(f, p, out, cnt, [&](const Poi& poi, const Match& m, std::uint32_t sub[8]) {
    const int x0 = poi.x + m.bx;
    const int y0 = poi.y + m.by;
    auto P = [&](int u, int v) { return f.next.at(x0 + u, y0 + v); };
    auto h = [&](int u, int v) { return avg_floor(P(u, v), P(u + 1, v)); };
    auto g = [&](int u, int v) { return avg_floor(P(u, v), P(u, v + 1)); };
    // The diagonal is the average of two HORIZONTAL averages, each floored (SPEC §3).
    auto d = [&](int u, int v) { return avg_floor(h(u, v), h(u, v + 1)); };
    for (int k = 0; k < 8; ++k) {
      sub[k] = block_sad(
          f.prev, poi.x, poi.y, [&](int c, int r) { return direction_value(k, c, r, h, g, d); },
          cnt);
      cnt.interpolations += (k % 2 == 1) ? 2 * 64 : 64;  // odd k are the diagonals
    }
  });
}

}  // namespace pxflow::ref
