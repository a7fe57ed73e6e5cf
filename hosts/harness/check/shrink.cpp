#include "shrink.hpp"

#include <algorithm>
#include <cstring>

#include "exactness.hpp"
#include "grid.hpp"
#include "interrupt.hpp"

namespace pxflow {
namespace {

// Where a candidate stands: the pair, its parameters and the POI whose read window is kept.
struct Candidate {
  OwnedPair pair;
  Params params;
  int x = 0, y = 0;  // the failing POI's block in prev
};

class Shrinker {
 public:
  Shrinker(const PairRunner& run, const ShrinkLimits& limits, Stage stage)
      : run_(run), limits_(limits), stage_(stage), t0_(std::chrono::steady_clock::now()) {}

  bool spent() const {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    return runs_ >= limits_.max_runs || s >= limits_.seconds;
  }

  // True when the backend still differs from the reference on `c` in the stage being chased; the
  // first POI that does is then remembered with both records.
  bool fails(const Candidate& c) {
    if (spent()) return false;
    // Ctrl-C stops the shrinking too, not only the next case.
    stop_if_interrupted("the shrinking of a reproducer (" + std::to_string(runs_) + " runs)");
    ++runs_;
    const FramePair view = c.pair.view();
    const std::span<const FramePair> pairs(&view, 1);
    const RunOutcome got = run_(pairs, c.params);
    const ReferenceAnswer want = reference_answer(pairs, c.params);
    if (!got.error.empty() || got.records.size() != want.records.size()) return false;
    for (std::size_t n = 0; n < want.records.size(); ++n) {
      const Stage s = differing_stage(want.records[n], got.records[n]);
      if (s == Stage::kSame) continue;
      if (s != stage_) return false;
      last_poi_ = n;
      last_want_ = want.records[n];
      last_got_ = got.records[n];
      return true;
    }
    return false;
  }

  int runs() const { return runs_; }
  std::size_t last_poi() const { return last_poi_; }
  const PoiRecord& last_want() const { return last_want_; }
  const PoiRecord& last_got() const { return last_got_; }

 private:
  const PairRunner& run_;
  ShrinkLimits limits_;
  Stage stage_;
  std::chrono::steady_clock::time_point t0_;
  int runs_ = 0;
  std::size_t last_poi_ = 0;
  PoiRecord last_want_{}, last_got_{};
};

// The w x h pair whose pixel (u, v) is the original's (x0 + u, y0 + v), 0 outside it.
OwnedPair crop_pair(const OwnedPair& o, int x0, int y0, int w, int h) {
  OwnedPair c{o.name, w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h),
              std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h)};
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      const int x = x0 + u, y = y0 + v;
      if (x < 0 || y < 0 || x >= o.width || y >= o.height) continue;
      c.prev[v * w + u] = o.prev[y * o.width + x];
      c.next[v * w + u] = o.next[y * o.width + x];
    }
  return c;
}

// The smallest pair that still fails: the POI moved to the grid's first point, (S+1, S+1), of a
// frame of 2S+11 pixels a side (the smallest valid one: its grid is that one point), then of
// 64x64 (a kernel may take another path on a frame that small), else the pair as it is.
std::optional<Candidate> cropped(const OwnedPair& pair, const Params& p, const Poi& at,
                                 Shrinker& s) {
  const int S = p.search_radius, smallest = min_frame_side(S);
  std::vector<std::pair<int, int>> sizes = {{smallest, smallest}};
  const int w64 = std::max(64, smallest);
  if (w64 > smallest && (w64 < pair.width || w64 < pair.height))
    sizes.push_back({std::min(w64, pair.width), std::min(w64, pair.height)});
  for (auto [w, h] : sizes) {
    Candidate c{crop_pair(pair, at.x - S - 1, at.y - S - 1, w, h), p, S + 1, S + 1};
    c.params.width = w;
    c.params.height = h;
    if (grid_axis(w, c.params).front() != S + 1) continue;  // the POI would not land there
    if (s.fails(c)) return c;
  }
  Candidate whole{pair, p, at.x, at.y};
  if (s.fails(whole)) return whole;
  return std::nullopt;
}

// Applies `change` to a copy of c and keeps the copy when it still fails.
template <class Change>
bool try_change(Candidate& c, Shrinker& s, Change&& change) {
  Candidate t = c;
  change(t);
  if (t.pair.prev == c.pair.prev && t.pair.next == c.pair.next) return false;
  if (!s.fails(t)) return false;
  c = std::move(t);
  return true;
}

struct Rect {
  int x0, y0, x1, y1;  // [x0, x1) x [y0, y1)
  bool holds(int x, int y) const { return x >= x0 && y >= y0 && x < x1 && y < y1; }
};

// Every pixel outside the POI's read windows set to 0, then each tile of the windows flattened
// to its mean, then every value quantised as coarsely as still fails.
void simplify(Candidate& c, Shrinker& s) {
  const int S = c.params.search_radius, w = c.pair.width, h = c.pair.height;
  const Rect block{c.x, c.y, c.x + 8, c.y + 8};
  const Rect window{c.x - S - 1, c.y - S - 1, c.x + S + 9, c.y + S + 9};
  try_change(c, s, [&](Candidate& t) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (!block.holds(x, y)) t.pair.prev[y * w + x] = 0;
        if (!window.holds(x, y)) t.pair.next[y * w + x] = 0;
      }
  });
  // Tiles of about a sixth of the window's side: at most ~40 runs per frame.
  auto flatten = [&](std::vector<std::uint8_t> OwnedPair::*frame, const Rect& r, int tile) {
    for (int ty = r.y0; ty < r.y1 && !s.spent(); ty += tile)
      for (int tx = r.x0; tx < r.x1 && !s.spent(); tx += tile)
        try_change(c, s, [&](Candidate& t) {
          std::vector<std::uint8_t>& px = t.pair.*frame;
          int sum = 0, n = 0;
          for (int y = ty; y < std::min(ty + tile, r.y1); ++y)
            for (int x = tx; x < std::min(tx + tile, r.x1); ++x) sum += px[y * w + x], ++n;
          for (int y = ty; y < std::min(ty + tile, r.y1); ++y)
            for (int x = tx; x < std::min(tx + tile, r.x1); ++x)
              px[y * w + x] = static_cast<std::uint8_t>(sum / n);
        });
  };
  flatten(&OwnedPair::prev, block, 4);
  flatten(&OwnedPair::next, window, std::max(4, (2 * S + 10) / 6));
  for (int shift = 7; shift >= 1 && !s.spent(); --shift)
    if (try_change(c, s, [&](Candidate& t) {
          for (auto* px : {&t.pair.prev, &t.pair.next})
            for (auto& v : *px) v = static_cast<std::uint8_t>(v >> shift << shift);
        }))
      break;
}

}  // namespace

std::optional<Reproducer> shrink_mismatch(const OwnedPair& pair, const Params& p, std::size_t poi,
                                          const PairRunner& run, const ShrinkLimits& limits) {
  const std::vector<Poi> grid = poi_grid(p);
  if (poi >= grid.size()) return std::nullopt;
  // The stage chased is the one the pair fails in; a simplification that changes it is refused.
  const FramePair view = pair.view();
  const RunOutcome first = run(std::span<const FramePair>(&view, 1), p);
  if (!first.error.empty() || first.records.size() != grid.size()) return std::nullopt;
  const ReferenceAnswer want = reference_answer(std::span<const FramePair>(&view, 1), p);
  const Stage stage = differing_stage(want.records[poi], first.records[poi]);
  if (stage == Stage::kSame) return std::nullopt;

  Shrinker s(run, limits, stage);
  std::optional<Candidate> c = cropped(pair, p, grid[poi], s);
  if (!c) return std::nullopt;
  Reproducer r;
  r.cropped = c->pair.width != pair.width || c->pair.height != pair.height;
  simplify(*c, s);
  // The last run that failed was of the candidate kept: its records describe the reproducer.
  r.poi = s.last_poi();
  r.pair = std::move(c->pair);
  r.pair.name = pair.name + ", shrunk";
  r.params = c->params;
  r.stage = stage;
  r.what = stage_words(r.pair.view(), r.params, s.last_want(), s.last_got());
  r.runs = s.runs() + 1;  // and the run that found the stage
  return r;
}

}  // namespace pxflow
