// Generated frame pairs: seeded random pairs and hostile patterns (STYLE.md guideline 6). Pure
// C++, reproducible on every host from (size, seed): the tests and the checker share them.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "frame.hpp"

namespace pxflow {

// A frame pair that owns its pixels (packed rows, stride = width).
struct OwnedPair {
  std::string name;  // e.g. "random/seed=7", "hostile/checkerboard"
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> prev, next;

  FramePair view() const {
    return {{width, height, width, prev.data()}, {width, height, width, next.data()}};
  }
};

// SplitMix64: tiny, fast, and the same sequence on every platform and compiler.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  int uniform(int lo, int hi);  // inclusive
 private:
  std::uint64_t state_;
};

// One random pair from `seed`. The seed also picks the kind, so a run over many seeds covers:
// pure noise, shifted texture (integer and half-pixel shifts up to the search radius, with and
// without noise), smooth texture, low-contrast texture, and unrelated frames.
OwnedPair random_pair(int width, int height, int search_radius, std::uint64_t seed);

// Uniform-noise texture moved by a seeded whole-pixel shift within the search radius, with
// light noise: nearly every POI passes both thresholds, so every pair costs the full kernel
// (the paper's "all POIs accepted" case). The benchmark's input.
OwnedPair shifted_texture_pair(int width, int height, int search_radius, std::uint64_t seed);

// Hostile patterns: all 0, all 255, max-difference checkerboards, periodic textures that make
// SAD ties, LSB-only contrast (catches round-up averaging), shifts to the edge of the search
// window, and an identical pair. `search_radius` places the edge shifts.
std::vector<OwnedPair> hostile_pairs(int width, int height, int search_radius);

// next(x, y) = prev(x - sx, y - sy) for a shift (sx, sy), edges filled from `fill_seed`.
void shift_into(const std::vector<std::uint8_t>& prev, std::vector<std::uint8_t>& next, int width,
                int height, int sx, int sy, std::uint64_t fill_seed);

}  // namespace pxflow
