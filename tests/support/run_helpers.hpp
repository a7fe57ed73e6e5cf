// Small helpers for running the reference in tests: sentinel-filled record buffers, so that a
// record a kernel forgot to write cannot pass for a written one.
#pragma once
#include <cstring>
#include <vector>

#include "exactness.hpp"
#include "grid.hpp"
#include "kernel.hpp"

namespace pxflow::test {

using pxflow::sentinel_records;

inline std::vector<PoiRecord> run_ref(RefVariant v, const FramePair& f, const Params& p,
                                      OpCounts* counts = nullptr) {
  auto out = sentinel_records(poi_count(p));
  OpCounts local;
  reference_flow(v, f, p, out, counts ? *counts : local);
  return out;
}

inline Params with_size(Params p, int w, int h) {
  p.width = w;
  p.height = h;
  return p;
}

}  // namespace pxflow::test
