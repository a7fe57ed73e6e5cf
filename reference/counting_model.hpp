// The counting model of docs/counting.md as a function: the counts a variant must report for a
// batch, computed from the batch's records (which POIs were searched, which accepted) instead of
// by running the variant. `pxflow check` holds every counting backend to it; the counts tests
// hold the reference variants themselves to it.
#pragma once
#include <cstddef>
#include <span>

#include "kernel.hpp"
#include "params.hpp"
#include "record.hpp"

namespace pxflow {

// What variant `v` counts for `pairs` frame pairs whose records (poi_count(p) per pair) are
// `records`: 6 SAD ops per POI, 16 per candidate for a searched POI, 128 per accepted POI; and
// interpolations of 768 (original) or 300 (local) per accepted POI, or 3 per frame pixel per
// pair (global). The result is marked counted.
OpCounts model_counts(RefVariant v, std::span<const PoiRecord> records, const Params& p,
                      std::size_t pairs);

}  // namespace pxflow
