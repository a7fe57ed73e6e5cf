#include "grid.hpp"

namespace pxflow {

std::vector<int> grid_axis(int side, const Params& p) {
  const int lo = p.search_radius + 1;
  const int hi = side - (p.search_radius + 1) - p.tile;
  const int step = (hi - lo) / p.blocks + 1;  // integer division, as in the firmware
  std::vector<int> coords;
  for (int c = lo; c < hi; c += step) coords.push_back(c);
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
  return grid_axis(p.width, p).size() * grid_axis(p.height, p).size();
}

}  // namespace pxflow
