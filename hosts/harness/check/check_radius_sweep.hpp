// The radius sweep of the limit cases (docs/check-corpus.md, "Every row at its own edges"): for
// every search radius S a row accepts, frames whose POIs each have their best candidate planted at
// a chosen offset, so that over one S the best lands in every column of the window (every lane of
// a search vectorised over dx, whatever its vector length), in every row, at both corners, and,
// as decoys, one step outside the window (a search that reads one candidate too many finds a
// perfect match there that the window does not hold).
#pragma once
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "params.hpp"
#include "synthetic.hpp"

namespace pxflow {

// Where a POI's block is copied in `next`, relative to the POI (SPEC §3's dx, dy).
struct Offset {
  int dx = 0, dy = 0;
  bool operator==(const Offset&) const = default;
};

// The offsets of radius S: every dx of the window once (with dy running through the window in
// another order), both corners (-S,-S) and (S,S), and the six decoys one step outside the window
// where an off-by-one search over rows or over the flattened window would read.
std::vector<Offset> sweep_offsets(int S);

// The frame of the sweep at radius S with g x g POIs (B = g): POIs 2S+10 apart, so that each
// POI's planted block and decoys stay inside its own window and never touch a neighbour's; g = 1
// is the smallest frame S allows. A side that is a multiple of 4 is made one larger (same grid):
// lavapipe runs large radii on such widths some 200 times slower
// (docs/measurements/check-corpus.md).
Params sweep_params(int S, int g);

// A pair at `p` (a sweep_params frame): prev uniform noise, next independent noise with each POI's
// 8x8 block of prev copied to the POI plus offsets[(first + n) % size] for POI n. An in-window
// offset is then the POI's only exact match (SAD 0); a decoy leaves the window noise.
OwnedPair planted_pair(const Params& p, std::span<const Offset> offsets, std::size_t first,
                       std::uint64_t seed);

// One step of a row's sweep: its parameters and how many pairs cover sweep_offsets(S).
struct SweepStep {
  Params params;
  int pairs = 0;
};

// The sweep of a row whose predicate is `accepts`: for every S from 1 to 31 it accepts at the
// smallest frame, the largest grid g <= ceil(sqrt(offsets)) it accepts within `max_pixels`
// (fewer POIs per pair and more pairs where it accepts less).
std::vector<SweepStep> radius_sweep(const std::function<bool(const Params&)>& accepts,
                                    std::int64_t max_pixels);

}  // namespace pxflow
