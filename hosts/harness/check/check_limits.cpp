#include "check_limits.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "check_radius_sweep.hpp"
#include "errors.hpp"
#include "fnv1a.hpp"
#include "grid.hpp"
#include "result_json.hpp"
#include "synthetic.hpp"

namespace pxflow {
namespace {

constexpr int kMiddleRadius = 12;  // see spec_corners()

bool valid(const Params& p) {
  try {
    validate(p);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

Params at(int w, int h, int S, int B) {
  Params p = profile(kDefaultProfile);
  p.width = w, p.height = h, p.search_radius = S, p.blocks = B;
  return p;
}

// "65x63 S=4 B=8", then what differs from the default profile's thresholds.
std::string setting_text(const Params& p) {
  const Params d = profile(kDefaultProfile);
  std::string s = std::to_string(p.width) + "x" + std::to_string(p.height) +
                  " S=" + std::to_string(p.search_radius) + " B=" + std::to_string(p.blocks);
  if (p.feature_threshold != d.feature_threshold) s += " FT=" + std::to_string(p.feature_threshold);
  if (p.sad_threshold != d.sad_threshold) s += " VT=" + std::to_string(p.sad_threshold);
  if (p.min_count != d.min_count) s += " MINCOUNT=" + std::to_string(p.min_count);
  if (p.hist_filter != d.hist_filter) s += p.hist_filter ? " HF on" : " HF off";
  return s;
}

// SPEC §1's corners at the default profile: every backend is meant to handle these unless its
// predicate says otherwise.
std::vector<LimitProbe> spec_corners() {
  const Params d = profile(kDefaultProfile);
  const int S = d.search_radius, B = d.blocks;
  auto thresholds = [&](int ft, int vt, int mc) {
    Params p = d;
    p.feature_threshold = ft, p.sad_threshold = vt, p.min_count = mc;
    return p;
  };
  Params no_hf = d;
  no_hf.hist_filter = false;
  std::vector<LimitProbe> corners = {
      {"smallest-frame",
       {},
       at(min_frame_side(kMinSearchRadius), min_frame_side(kMinSearchRadius), kMinSearchRadius, B)},
      {"smallest-frame", {}, at(min_frame_side(S), min_frame_side(S), S, B)},
      {"largest-radius-smallest-frame",
       {},
       at(min_frame_side(kMaxSearchRadius), min_frame_side(kMaxSearchRadius), kMaxSearchRadius, B)},
      // A radius between the default and 31 whose window rows (2S+10 = 34 bytes) take three
      // 16-byte copies and whose SIMD row reads (avx2: 41 bytes) pass the right edge: the CPU
      // rows copy such windows (kernels/cpu/poi_loop.cpp), which neither 4 nor 31 makes them do.
      {"middle-radius-smallest-frame",
       {},
       at(min_frame_side(kMiddleRadius), min_frame_side(kMiddleRadius), kMiddleRadius, B)},
      {"odd-size", {}, at(65, 64, S, B)},  // an odd width alone, an odd height alone, both
      {"odd-size", {}, at(64, 63, S, B)},
      {"odd-size", {}, at(63, 65, S, B)},
      {"smallest-radius", {}, at(64, 64, kMinSearchRadius, B)},
      {"smallest-blocks", {}, at(64, 64, S, kMinBlocks)},
      {"largest-blocks", {}, at(64, 64, S, kMaxBlocks)},
      {"every-poi-rejected", {}, thresholds(kMaxThreshold, d.sad_threshold, d.min_count)},
      {"every-poi-accepted", {}, thresholds(0, kMaxThreshold, d.min_count)},
      {"no-match-accepted", {}, thresholds(d.feature_threshold, 0, d.min_count)},
      {"min-count-0", {}, thresholds(d.feature_threshold, d.sad_threshold, 0)},
      {"min-count-max", {}, thresholds(d.feature_threshold, d.sad_threshold, kMaxThreshold)},
      {"hist-filter-off", {}, no_hf},
  };
  for (LimitProbe& c : corners) c.every_row = true;
  return corners;
}

// The row's own edges at the default profile: the largest square frame, the widest and tallest
// strip at the smallest other side, the largest radius and grid (64x64) it accepts. The radius
// is searched at the smallest frame S = 31 allows (one POI): lavapipe needs minutes for the 49
// POIs of 128x128 at S = 31 (docs/measurements/check-corpus.md). A row refusing that frame
// (m4-qemu: 4096 pixels) is searched at the largest odd square up to it that it accepts, with one
// POI (B = 1): lavapipe runs a 64x64 frame at S = 25 some 200 times slower than 63x63 or 73x73
// (docs/measurements/check-corpus.md).
void row_probes(const LimitRow& r, std::vector<LimitProbe>& out) {
  auto ok = [&](const Params& p) { return valid(p) && r.unsupported(p).empty(); };
  const Params d = profile(kDefaultProfile);
  const int S = d.search_radius, B = d.blocks, m = min_frame_side(S);
  auto affordable = [](const Params& p) {
    return std::int64_t{p.width} * p.height <= kAffordableLimitPixels;
  };
  auto add = [&](const char* what, const Params& p) {
    if (affordable(p)) out.push_back({what, {r.name}, p});
  };
  constexpr int kLargestSquareSide = 8192;  // kMaxFramePixels = 8192 * 8192
  if (auto n = largest_accepted(m, kLargestSquareSide, [&](int n) { return ok(at(n, n, S, B)); }))
    add("largest-square", at(*n, *n, S, B));
  if (auto w = largest_accepted(m, kMaxFrameSide, [&](int w) { return ok(at(w, m, S, B)); }))
    add("widest", at(*w, m, S, B));
  if (auto h = largest_accepted(m, kMaxFrameSide, [&](int h) { return ok(at(m, h, S, B)); }))
    add("tallest", at(m, *h, S, B));
  int side = min_frame_side(kMaxSearchRadius), grid = B;
  if (!ok(at(side, side, kMinSearchRadius, grid))) {
    grid = kMinBlocks;
    side = largest_accepted(min_frame_side(kMinSearchRadius), side, [&](int n) {
             return ok(at(n, n, kMinSearchRadius, grid));
           }).value_or(0);
    side -= side % 2 == 0 && side > min_frame_side(kMinSearchRadius);
  }
  if (auto s = largest_accepted(kMinSearchRadius, kMaxSearchRadius,
                                [&](int s) { return ok(at(side, side, s, grid)); }))
    add("largest-radius", at(side, side, *s, grid));
  if (auto b =
          largest_accepted(kMinBlocks, kMaxBlocks, [&](int b) { return ok(at(64, 64, S, b)); }))
    add("largest-blocks", at(64, 64, S, *b));
  for (const SweepStep& step : radius_sweep(ok, kSweepPixels))
    out.push_back({"radius-sweep", {r.name}, step.params, false, step.pairs});
}

}  // namespace

std::string LimitProbe::what() const {
  std::string s = kind;
  for (std::size_t i = 0; i < rows.size(); ++i) s += (i ? "," : " of ") + rows[i];
  return s;
}

std::optional<int> largest_accepted(int lo, int hi, const std::function<bool(int)>& accepts) {
  if (lo > hi || !accepts(lo)) return std::nullopt;
  if (accepts(hi)) return hi;
  // accepts(lo) and !accepts(hi): halve the gap until they are neighbours.
  while (hi - lo > 1) {
    const int mid = lo + (hi - lo) / 2;
    (accepts(mid) ? lo : hi) = mid;
  }
  return lo;
}

std::vector<LimitProbe> limit_probes(std::span<const LimitRow> rows) {
  std::vector<LimitProbe> found = spec_corners();
  for (const LimitRow& r : rows) row_probes(r, found);
  // One case per problem, named the same whatever rows are selected: a row's edge that is one of
  // SPEC's corners is that corner (every row's case already); the same edge of several rows is
  // one case for all of them.
  std::vector<LimitProbe> out;
  std::vector<std::string> corners, keys;
  for (LimitProbe& p : found) {
    const std::string problem = params_json(p.params).dump() + (p.sweep_pairs ? " sweep" : "");
    if (p.every_row) {
      corners.push_back(problem);
    } else if (std::find(corners.begin(), corners.end(), problem) != corners.end()) {
      continue;
    }
    const std::string key = p.kind + " " + problem;
    const auto k = std::find(keys.begin(), keys.end(), key);
    if (k == keys.end()) {
      keys.push_back(key);
      out.push_back(std::move(p));
    } else {
      LimitProbe& first = out[static_cast<std::size_t>(k - keys.begin())];
      first.rows.insert(first.rows.end(), p.rows.begin(), p.rows.end());
    }
  }
  // SPEC's corners in their order, then the rows' edges in an order of their own (by kind and
  // parameters): a row's cases come in the same order whatever rows precede it.
  std::vector<std::size_t> order(out.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (out[a].every_row || out[b].every_row) return out[a].every_row && !out[b].every_row;
    return keys[a] < keys[b];
  });
  std::vector<LimitProbe> sorted;
  for (std::size_t i : order) sorted.push_back(std::move(out[i]));
  return sorted;
}

std::vector<CheckCase> limit_cases(std::span<const LimitRow> rows, std::uint64_t seed) {
  std::vector<CheckCase> cases;
  for (const LimitProbe& probe : limit_probes(rows)) {
    const Params& p = probe.params;
    const std::string setting = setting_text(p);
    CheckCase c{"limits/" + probe.kind, setting, p, {}, {}};
    if (!probe.every_row) c.rows = probe.rows;
    // Seeds from the case itself, apart from the random cases' seeds (seed * 1000003 + n).
    Fnv1a hash(seed * 1000003u + 7000000u);
    const std::string label = c.name + " " + setting;
    hash.add(label.data(), label.size());
    const std::uint64_t s = hash.value();
    if (probe.sweep_pairs) {
      const auto offsets = sweep_offsets(p.search_radius);
      const std::size_t per_pair = poi_count(p);
      for (int n = 0; n < probe.sweep_pairs; ++n)
        c.pairs.push_back(planted_pair(p, offsets, n * per_pair, s + n));
    } else {  // two random pairs where they are cheap; the large frames one
      const int pairs = std::int64_t{p.width} * p.height <= 128 * 128 ? 2 : 1;
      for (int n = 0; n < pairs; ++n)
        c.pairs.push_back(random_pair(p.width, p.height, p.search_radius, s + n));
    }
    cases.push_back(std::move(c));
  }
  return cases;
}

bool is_limit_case(const CheckCase& c) { return c.name.starts_with("limits/"); }

std::string limit_entry(const CheckCase& c, const std::string& row) {
  return c.name + (c.rows.empty() ? "" : " of " + row) + " " + c.setting;
}

}  // namespace pxflow
