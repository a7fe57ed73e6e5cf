// Exactness, the one way pxflow compares a backend with the reference: outputs pre-filled with a
// sentinel (an unwritten record cannot pass for a written one), every record compared byte for
// byte with ref-original's, the frame flow by its float bits, and one line per mismatch in a
// fixed field order. `pxflow check` and every family's tests use it; pure C++ (no OpenCV) so
// that the NEON cross test, built for AArch64, shares it.
#pragma once
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "frame.hpp"
#include "params.hpp"
#include "record.hpp"

namespace pxflow {

// The byte every output record is filled with before a backend runs.
inline constexpr unsigned char kUnwrittenSentinel = 0xA5;

std::vector<PoiRecord> sentinel_records(std::size_t n);

// ref-original's answer for a batch: its records (poi_count(p) per pair) and frame estimates.
struct ReferenceAnswer {
  std::vector<PoiRecord> records;
  std::vector<FrameResult> results;
  OpCounts counts;  // ref-original's own, held to its counting model like every row's
};
ReferenceAnswer reference_answer(std::span<const FramePair> pairs, const Params& p);

// What a line names: the backend, the case and its parameter setting.
struct CaseLabel {
  std::string who, case_name, setting;
  std::string prefix() const;  // "FAIL <who> case=<case_name>[<setting>]"
};

struct Comparison {
  long mismatches = 0;             // records and flow fields that differ
  std::vector<std::string> lines;  // at most max_lines of them, then an "... and N more" line
  bool ok() const { return mismatches == 0; }
  std::string text() const;  // the lines, one per line (for a test's failure message)
};

// Compares `got` (a backend's records for `pairs`) with `want`. Each mismatch line reads
// "<prefix> pair=<name> poi=<n> (x=..,y=..) field=<f> expected=<v> got=<v>" (or
// "field=flow_x expected=<bits> got=<bits>"); `detail`, when given, is appended to record lines
// (the checker's --verbose block dump).
using RecordDetail = std::function<std::string(std::size_t pair, const PoiRecord& want)>;
Comparison compare_with_reference(const CaseLabel& label, std::span<const std::string> pair_names,
                                  const Params& p, const ReferenceAnswer& want,
                                  std::span<const PoiRecord> got, int max_lines,
                                  const RecordDetail& detail = {});

// The whole check of one batch: `run` writes into sentinel-filled records, which are compared
// with ref-original's answer. An exception from `run` is one "<prefix> error: ..." line.
using BatchRun =
    std::function<void(std::span<const FramePair>, const Params&, std::span<PoiRecord>)>;
Comparison check_exact(const CaseLabel& label, std::span<const FramePair> pairs,
                       std::span<const std::string> pair_names, const Params& p,
                       const BatchRun& run, int max_lines = 5);

}  // namespace pxflow
