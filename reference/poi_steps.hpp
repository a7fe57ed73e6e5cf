// The per-POI steps shared by the three reference variants (SPEC §3). The variants differ only
// in how they produce the half-pixel values; everything else is here, once.
#pragma once
#include <cstdint>
#include <span>

#include "frame.hpp"
#include "grid.hpp"
#include "params.hpp"
#include "primitives.hpp"
#include "record.hpp"

namespace pxflow::ref {

// Half-pixel step (sx, sy) of direction k (SPEC §3 table); k = 8 is the integer match.
inline constexpr int kStepX[9] = {+1, +1, 0, -1, -1, -1, 0, +1, 0};
inline constexpr int kStepY[9] = {0, +1, +1, +1, 0, -1, -1, -1, 0};

// Step 1: 24 absolute differences over the central 4x4 of prev's block. Charged as the
// firmware computes it: three 4-byte row differences and three 4-byte column differences.
std::uint16_t feature(const FrameView& prev, int i, int j, OpCounts& c);

struct Match {
  int bx = 0;
  int by = 0;
  std::uint32_t sad = 0;
};

// Step 2: full search over dx, dy in -S..S, raster order, strictly smaller SAD wins.
Match integer_search(const FramePair& f, int i, int j, int S, OpCounts& c);

// 8x8 SAD of prev's block at (i, j) against value(c, r). Charged 16 ops: two 4-byte halves per
// row, the firmware's USAD8/USADA8 sequence.
template <class Value>
std::uint32_t block_sad(const FrameView& prev, int i, int j, Value&& value, OpCounts& cnt) {
  std::uint32_t acc = 0;
  for (int r = 0; r < 8; ++r) {
    for (int half = 0; half < 2; ++half) {
      for (int c = 4 * half; c < 4 * half + 4; ++c) {
        const int d = int{prev.at(i + c, j + r)} - int{value(c, r)};
        acc += static_cast<std::uint32_t>(d < 0 ? -d : d);
      }
      ++cnt.sad_ops;
    }
  }
  return acc;
}

// The value of block pixel (c, r) in half-pixel direction k (SPEC §3), given the three planes
// as callables h(u, v), g(u, v), d(u, v) in block coordinates.
template <class H, class G, class D>
std::uint8_t direction_value(int k, int c, int r, H&& h, G&& g, D&& d) {
  switch (k) {
    case 0:
      return h(c, r);
    case 1:
      return d(c, r);
    case 2:
      return g(c, r);
    case 3:
      return d(c - 1, r);
    case 4:
      return h(c - 1, r);
    case 5:
      return d(c - 1, r - 1);
    case 6:
      return g(c, r - 1);
    default:
      return d(c, r - 1);  // k == 7
  }
}

// Step 3's vote and step 4: starting from (best, dir 8), direction k = 0..7 replaces only when
// strictly smaller, so ties keep the integer match or the lower k. Writes dir, sub, hx, hy.
void select_half_pixel(PoiRecord& rec, const Match& m, const std::uint32_t sub[8]);

// Step 4 for the vote's direction `dir` (0..7, or kDirNone for the integer match m): dir, hx, hy.
inline void record_direction(PoiRecord& rec, const Match& m, int dir) {
  rec.dir = static_cast<std::uint8_t>(dir);
  rec.hx = static_cast<std::int8_t>(2 * m.bx + kStepX[dir]);
  rec.hy = static_cast<std::int8_t>(2 * m.by + kStepY[dir]);
}

// Runs steps 1-4 for every POI of the grid. `half_sads(poi, match, sub)` fills the eight
// half-pixel SADs of an accepted POI: the only part in which the variants differ.
template <class HalfSads>
void run_pois(const FramePair& f, const Params& p, std::span<PoiRecord> out, OpCounts& cnt,
              HalfSads&& half_sads) {
  std::size_t n = 0;
  for (const Poi& poi : poi_grid(p)) {
    PoiRecord& rec = out[n++];
    rec = PoiRecord{};  // every field a status does not define, and the padding, is 0
    rec.x = static_cast<std::uint16_t>(poi.x);
    rec.y = static_cast<std::uint16_t>(poi.y);
    rec.dir = kDirNone;
    rec.feature = feature(f.prev, poi.x, poi.y, cnt);
    if (rec.feature < p.feature_threshold) {
      rec.status = kDropped;
      continue;
    }
    const Match m = integer_search(f, poi.x, poi.y, p.search_radius, cnt);
    rec.dx = static_cast<std::int8_t>(m.bx);
    rec.dy = static_cast<std::int8_t>(m.by);
    rec.sad = static_cast<std::uint16_t>(m.sad);
    if (!(m.sad < static_cast<std::uint32_t>(p.sad_threshold))) {
      rec.status = kRejected;
      continue;
    }
    rec.status = kAccepted;
    std::uint32_t sub[8];
    half_sads(poi, m, sub);
    select_half_pixel(rec, m, sub);
  }
}

}  // namespace pxflow::ref
