#include "exactness.hpp"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>

#include "estimate.hpp"
#include "grid.hpp"
#include "kernel.hpp"
#include "record_diff.hpp"

namespace pxflow {
namespace {

std::string bits_hex(float v) {
  char b[16];
  std::snprintf(b, sizeof b, "%08x", std::bit_cast<std::uint32_t>(v));
  return b;
}

}  // namespace

std::vector<PoiRecord> sentinel_records(std::size_t n) {
  std::vector<PoiRecord> out(n);
  std::memset(out.data(), kUnwrittenSentinel, n * sizeof(PoiRecord));
  return out;
}

ReferenceAnswer reference_answer(std::span<const FramePair> pairs, const Params& p) {
  const std::size_t per = poi_count(p);
  ReferenceAnswer a;
  a.records = sentinel_records(per * pairs.size());
  OpCounts counts;
  for (std::size_t n = 0; n < pairs.size(); ++n) {
    const auto mine = std::span(a.records).subspan(n * per, per);
    reference_flow(RefVariant::kOriginal, pairs[n], p, mine, counts);
    a.results.push_back(estimate_flow(mine, p));
  }
  a.counts = counts;
  return a;
}

std::string CaseLabel::prefix() const {
  return "FAIL " + who + " case=" + case_name + "[" + setting + "]";
}

std::string Comparison::text() const {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

Comparison compare_with_reference(const CaseLabel& label, std::span<const std::string> pair_names,
                                  const Params& p, const ReferenceAnswer& want,
                                  std::span<const PoiRecord> got, int max_lines,
                                  const RecordDetail& detail) {
  Comparison c;
  const std::size_t per = poi_count(p);
  auto emit = [&](std::string line) {
    if (++c.mismatches <= max_lines) c.lines.push_back(std::move(line));
  };
  for (std::size_t pair = 0; pair < pair_names.size(); ++pair) {
    const std::string where = label.prefix() + " pair=" + pair_names[pair];
    for (std::size_t n = 0; n < per; ++n) {
      const PoiRecord& w = want.records[pair * per + n];
      const PoiRecord& g = got[pair * per + n];
      const std::optional<FieldDiff> d =
          untouched(g, kUnwrittenSentinel)
              ? FieldDiff{"record", "written", "never written (sentinel intact)"}
              : first_difference(w, g);
      if (!d) continue;
      std::string line = where + " poi=" + std::to_string(n) + " (x=" + std::to_string(w.x) +
                         ",y=" + std::to_string(w.y) + ") field=" + d->field +
                         " expected=" + d->expected + " got=" + d->got;
      if (detail && c.mismatches < max_lines) {
        // Two appends, not "\n" + detail(): GCC 12 warns on that one (-Wrestrict, a false
        // positive, GCC bug 105329).
        line += '\n';
        line += detail(pair, w);
      }
      emit(std::move(line));
    }
    FrameResult r;
    try {
      r = estimate_flow(got.subspan(pair * per, per), p);
    } catch (const std::out_of_range& e) {  // a record no estimate can use: a failure line
      emit(where + " field=flow_x,flow_y not estimated: " + e.what());
      continue;
    }
    const FrameResult& e = want.results[pair];
    for (auto [field, a, b] :
         {std::tuple{"flow_x", e.flow_x, r.flow_x}, std::tuple{"flow_y", e.flow_y, r.flow_y}})
      if (std::bit_cast<std::uint32_t>(a) != std::bit_cast<std::uint32_t>(b))
        emit(where + " field=" + field + " expected=" + bits_hex(a) + " got=" + bits_hex(b));
  }
  if (c.mismatches > max_lines)
    c.lines.push_back(label.prefix() + " ... and " + std::to_string(c.mismatches - max_lines) +
                      " more mismatches");
  return c;
}

Comparison check_exact(const CaseLabel& label, std::span<const FramePair> pairs,
                       std::span<const std::string> pair_names, const Params& p,
                       const BatchRun& run, int max_lines) {
  const ReferenceAnswer want = reference_answer(pairs, p);
  std::vector<PoiRecord> got = sentinel_records(want.records.size());
  try {
    run(pairs, p, got);
  } catch (const std::exception& e) {
    Comparison c;
    c.mismatches = 1;
    c.lines.push_back(label.prefix() + " error: " + e.what());
    return c;
  }
  return compare_with_reference(label, pair_names, p, want, got, max_lines);
}

}  // namespace pxflow
