// Inputs and comparisons shared by the GAP8 backend tests.
#pragma once
#include <string>
#include <vector>

#include "params.hpp"
#include "record.hpp"
#include "synthetic.hpp"

namespace pxflow::test {

// rubberwhale and basketball of the sample data (sample_data.hpp), w x h cut from the middle.
std::vector<OwnedPair> gap8_real_pairs(int w, int h);

// `n` seeded random pairs, every hostile pattern and the real pairs, at p's size.
std::vector<OwnedPair> gap8_corpus(const Params& p, int n_random, std::uint64_t seed);

}  // namespace pxflow::test
