#include "mismatch_stage.hpp"

#include <cstdlib>
#include <cstring>

#include "exactness.hpp"
#include "poi_steps.hpp"
#include "record_diff.hpp"

namespace pxflow {
namespace {

std::string status_name(int s) {
  switch (s) {
    case kDropped:
      return "dropped";
    case kRejected:
      return "rejected";
    case kAccepted:
      return "accepted";
  }
  return "status " + std::to_string(s);
}

// Appended piece by piece: GCC 12's -Wrestrict misfires on "(" + std::to_string() when inlined.
std::string xy(int dx, int dy) {
  std::string s = "(";
  s += std::to_string(dx) + "," + std::to_string(dy) + ")";
  return s;
}

std::string feature_words(const Params& p, const PoiRecord& want, const PoiRecord& got) {
  std::string s = "feature score: got " + std::to_string(got.feature) + " (" +
                  status_name(got.status) + "), the reference " + std::to_string(want.feature) +
                  " (" + status_name(want.status) + ")";
  if (got.feature == want.feature)
    s += ": the same score, a different test against FT=" + std::to_string(p.feature_threshold);
  return s;
}

// The reference's SAD of prev's block at the record's POI against next displaced by (dx, dy).
std::uint32_t true_sad(const FramePair& f, const PoiRecord& r, int dx, int dy) {
  OpCounts ignored;
  return ref::block_sad(
      f.prev, r.x, r.y, [&](int c, int row) { return f.next.at(r.x + dx + c, r.y + dy + row); },
      ignored);
}

std::string search_words(const FramePair& f, const Params& p, const PoiRecord& want,
                         const PoiRecord& got) {
  const int S = p.search_radius;
  std::string s = "SAD search: got candidate " + xy(got.dx, got.dy) + " with SAD " +
                  std::to_string(got.sad) + " (" + status_name(got.status) + ")";
  if (std::abs(got.dx) > S || std::abs(got.dy) > S)
    s += ", outside the search area (S=" + std::to_string(S) + ")";
  else
    s += ", the reference code gives that candidate SAD " +
         std::to_string(true_sad(f, want, got.dx, got.dy));
  s += "; the reference's best is " + xy(want.dx, want.dy) + " with SAD " +
       std::to_string(want.sad) + " (" + status_name(want.status) + ")";
  if (got.dx == want.dx && got.dy == want.dy && got.sad == want.sad)
    s += ": the same match, a different test against VT=" + std::to_string(p.sad_threshold);
  return s;
}

std::string half_pixel_words(const PoiRecord& want, const PoiRecord& got) {
  for (int k = 0; k < 8; ++k)
    if (want.sub[k] != got.sub[k])
      return "half-pixel refinement: sub[" + std::to_string(k) + "] (half step " +
             xy(ref::kStepX[k], ref::kStepY[k]) + ") got SAD " + std::to_string(got.sub[k]) +
             ", the reference " + std::to_string(want.sub[k]);
  if (want.dir != got.dir)
    return "half-pixel refinement: the same eight SADs, got dir " + std::to_string(got.dir) +
           ", the reference " + std::to_string(want.dir) + " (8: the integer match)";
  return "half-pixel refinement: got (hx,hy) " + xy(got.hx, got.hy) + ", the reference " +
         xy(want.hx, want.hy) + " for dir " + std::to_string(want.dir);
}

}  // namespace

Stage differing_stage(const PoiRecord& want, const PoiRecord& got) {
  if (std::memcmp(&want, &got, sizeof want) == 0) return Stage::kSame;
  if (untouched(got, kUnwrittenSentinel)) return Stage::kUnwritten;
  if (want.x != got.x || want.y != got.y) return Stage::kPlacement;
  const bool dropped = want.status == kDropped || got.status == kDropped;
  if (want.feature != got.feature || (dropped && want.status != got.status)) return Stage::kFeature;
  if (want.status != got.status || want.dx != got.dx || want.dy != got.dy || want.sad != got.sad)
    return Stage::kSearch;
  if (want.dir != got.dir || want.hx != got.hx || want.hy != got.hy ||
      std::memcmp(want.sub, got.sub, sizeof want.sub) != 0)
    return Stage::kHalfPixel;
  return Stage::kPadding;
}

const char* stage_name(Stage s) {
  switch (s) {
    case Stage::kSame:
      return "none";
    case Stage::kUnwritten:
      return "record never written";
    case Stage::kPlacement:
      return "POI grid";
    case Stage::kFeature:
      return "feature score";
    case Stage::kSearch:
      return "SAD search";
    case Stage::kHalfPixel:
      return "half-pixel refinement";
    case Stage::kPadding:
      return "record padding";
  }
  return "?";
}

std::string stage_words(const FramePair& pair, const Params& p, const PoiRecord& want,
                        const PoiRecord& got) {
  switch (differing_stage(want, got)) {
    case Stage::kFeature:
      return feature_words(p, want, got);
    case Stage::kSearch:
      return search_words(pair, p, want, got);
    case Stage::kHalfPixel:
      return half_pixel_words(want, got);
    case Stage::kPlacement:
      return "POI grid: got the POI at " + xy(got.x, got.y) + ", the reference " +
             xy(want.x, want.y);
    case Stage::kPadding:
      return "record padding: pad0/pad1 must be 0";
    case Stage::kUnwritten:
      return "record never written (the sentinel is intact)";
    case Stage::kSame:
      break;
  }
  return "frame estimate: every record agrees, the flow differs";
}

}  // namespace pxflow
