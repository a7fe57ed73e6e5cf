// The grid of points of interest (SPEC §2).
#pragma once
#include <cstdint>
#include <vector>

#include "params.hpp"

namespace pxflow {

struct Poi {
  int x = 0;  // top-left corner of the 8x8 block in prev
  int y = 0;
};

// One axis of the grid as device kernels take it: coordinates first, first + step, ...,
// count of them. lo = S+1, hi = side-(S+1)-T, step = (hi-lo)/B + 1 (integer division, as the
// firmware computes it), count = the values lo + k*step that are < hi. Kept exactly as the
// firmware computes it: for S = 3, 6 or 7 at 64 pixels it yields only 7 values.
struct GridAxis {
  int first = 0;
  int step = 1;
  int count = 0;
};
GridAxis grid_axis_triple(int side, const Params& p);

// The coordinates of grid_axis_triple(side, p), spelled out.
std::vector<int> grid_axis(int side, const Params& p);

// All POIs in record order: y outer, x inner, both ascending.
std::vector<Poi> poi_grid(const Params& p);

// Number of POIs poi_grid(p) returns, without building it.
std::size_t poi_count(const Params& p);

}  // namespace pxflow
