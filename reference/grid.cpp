#include "grid.hpp"

namespace pxflow {

GridAxis grid_axis_triple(int side, const Params& p) {
  const int lo = p.search_radius + 1;
  const int hi = side - (p.search_radius + 1) - p.tile;
  GridAxis a;
  a.first = lo;
  a.step = (hi - lo) / p.blocks + 1;  // integer division, as in the firmware
  // The firmware's loop `for (c = lo; c < hi; c += step)`; a step below 1 only arises when
  // hi <= lo, where that loop runs zero times.
  a.count = hi > lo ? (hi - lo - 1) / a.step + 1 : 0;
  if (a.step < 1) a.step = 1;
  return a;
}

std::vector<int> grid_axis(int side, const Params& p) {
  const GridAxis a = grid_axis_triple(side, p);
  std::vector<int> coords;
  coords.reserve(static_cast<std::size_t>(a.count));
  for (int k = 0; k < a.count; ++k) coords.push_back(a.first + k * a.step);
  return coords;
}

std::vector<Poi> poi_grid(const Params& p) {
  const auto xs = grid_axis(p.width, p);
  const auto ys = grid_axis(p.height, p);
  std::vector<Poi> pois;
  pois.reserve(xs.size() * ys.size());
  for (int y : ys)
    for (int x : xs) pois.push_back({x, y});
  return pois;
}

std::size_t poi_count(const Params& p) {
  return static_cast<std::size_t>(grid_axis_triple(p.width, p).count) *
         static_cast<std::size_t>(grid_axis_triple(p.height, p).count);
}

}  // namespace pxflow
