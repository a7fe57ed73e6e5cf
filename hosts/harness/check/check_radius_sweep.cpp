#include "check_radius_sweep.hpp"

#include <cmath>

#include "grid.hpp"

namespace pxflow {

std::vector<Offset> sweep_offsets(int S) {
  std::vector<Offset> out;
  const int n = 2 * S + 1;
  // dx = -S + k with dy = -S + k (S + 1) mod n: S + 1 is coprime to 2S + 1, so dy takes every
  // value of the window too, in an order that spreads the flattened index dy n + dx.
  for (int k = 0; k < n; ++k) out.push_back({-S + k, -S + (k * (S + 1)) % n});
  out.push_back({S, S});  // the window's last candidate (k = 0 gave its first, (-S, -S))
  // Decoys: beyond each side, and where one candidate too many lands in a search over rows of
  // the window (S + 1, S) or over the flattened window (-S, S + 1).
  for (Offset d : {Offset{S + 1, 0}, {-S - 1, 0}, {0, S + 1}, {0, -S - 1}, {S + 1, S}, {-S, S + 1}})
    out.push_back(d);
  return out;
}

Params sweep_params(int S, int g) {
  // Past one POI, hi - lo (SPEC §2) is the side less min_frame_side(S) - 1: g steps of 2S + 9.
  int side = g == 1 ? min_frame_side(S) : min_frame_side(S) - 1 + g * (2 * S + 9);
  if (g > 1 && side % 4 == 0) ++side;  // (hi - lo) / g stays 2S + 9: the same grid
  Params p = profile(kDefaultProfile);
  p.width = p.height = side;
  p.search_radius = S;
  p.blocks = g;
  return p;
}

OwnedPair planted_pair(const Params& p, std::span<const Offset> offsets, std::size_t first,
                       std::uint64_t seed) {
  const int w = p.width, h = p.height;
  Rng rng(seed);
  OwnedPair op{"planted/S=" + std::to_string(p.search_radius) + "/from=" + std::to_string(first) +
                   "/seed=" + std::to_string(seed),
               w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h),
               std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h)};
  for (auto& v : op.prev) v = static_cast<std::uint8_t>(rng.uniform(0, 255));
  for (auto& v : op.next) v = static_cast<std::uint8_t>(rng.uniform(0, 255));
  const auto pois = poi_grid(p);
  for (std::size_t n = 0; n < pois.size(); ++n) {
    const Offset o = offsets[(first + n) % offsets.size()];
    for (int r = 0; r < 8; ++r)
      for (int c = 0; c < 8; ++c)
        op.next[static_cast<std::size_t>(pois[n].y + o.dy + r) * w + pois[n].x + o.dx + c] =
            op.prev[static_cast<std::size_t>(pois[n].y + r) * w + pois[n].x + c];
  }
  return op;
}

std::vector<SweepStep> radius_sweep(const std::function<bool(const Params&)>& accepts,
                                    std::int64_t max_pixels) {
  std::vector<SweepStep> out;
  for (int S = kMinSearchRadius; S <= kMaxSearchRadius; ++S) {
    const int offsets = static_cast<int>(sweep_offsets(S).size());
    for (int g = static_cast<int>(std::ceil(std::sqrt(offsets))); g >= 1; --g) {
      const Params p = sweep_params(S, g);
      if (std::int64_t{p.width} * p.height > max_pixels || !accepts(p)) continue;
      out.push_back({p, (offsets + g * g - 1) / (g * g)});
      break;
    }
  }
  return out;
}

}  // namespace pxflow
