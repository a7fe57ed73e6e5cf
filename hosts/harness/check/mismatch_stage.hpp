// The first stage of SPEC §3 in which a backend's record departs from the reference's, in words a
// porter can act on: the feature score, the SAD search (with the candidate and both SADs, computed
// by the reference code on the pair), the half-pixel refinement, or the frame estimate.
#pragma once
#include <string>

#include "frame.hpp"
#include "params.hpp"
#include "record.hpp"

namespace pxflow {

enum class Stage { kSame, kUnwritten, kPlacement, kFeature, kSearch, kHalfPixel, kPadding };

// The stage of the first field in which `got` differs from `want` (SPEC §4's field order:
// x, y are the grid; status with feature, or dx, dy, sad; then dir, sub, hx, hy).
Stage differing_stage(const PoiRecord& want, const PoiRecord& got);

// "feature score", "SAD search", "half-pixel refinement", ...
const char* stage_name(Stage s);

// The stage and what differs in it, e.g. "SAD search: got candidate (1,0) with SAD 812 (the
// reference code gives it 830); the reference's best is (0,0) with SAD 790". `pair` is the pair
// both records are of.
std::string stage_words(const FramePair& pair, const Params& p, const PoiRecord& want,
                        const PoiRecord& got);

}  // namespace pxflow
