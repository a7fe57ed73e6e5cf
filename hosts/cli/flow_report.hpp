// What `pxflow flow` says about one pair: the JSON object (--json, one line of --jsonl), the CSV
// row (--csv), the human summary of a single pair and the one line per pair of a sequence.
#pragma once
#include <optional>
#include <span>
#include <string>

#include "backend.hpp"
#include "result_json.hpp"

namespace pxflow::cli {

// Everything known about one pair once the backend ran.
struct PairRun {
  std::string prev_name, next_name;
  std::string backend, implementation, device, profile;
  const Params* params = nullptr;
  FrameResult result;
  std::span<const PoiRecord> records;
  OpCounts counts;
  double host_seconds = 0;  // the backend's run(), steady_clock
  std::optional<Backend::DeviceTime> device_time;
};

// The JSON object: pxflow's version and commit, what ran (backend, implementation, device), the
// inputs, the frame size, profile and params, then the estimate as flow_result_json gives it
// (the records with their status names). No times: the bytes depend on the inputs only.
Json pair_json(const PairRun& run);

// Why the flow is 0 when MINCOUNT decided it ("" otherwise).
std::string mincount_note(const PairRun& run);

std::string csv_header();
std::string csv_row(int index, const PairRun& run);

// The multi-line summary of one pair (stdout of `pxflow flow A B`).
std::string pair_summary(const PairRun& run);
// One line per pair of a sequence.
std::string pair_line(int index, const PairRun& run);

}  // namespace pxflow::cli
