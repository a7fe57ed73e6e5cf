// What `pxflow flow` says about one pair: the JSON object (--json, one line of --jsonl), the CSV
// row (--csv), the human summary of a single pair and the one line per pair of a sequence.
#pragma once
#include <optional>
#include <span>
#include <string>

#include "backend.hpp"
#include "draw_flow.hpp"
#include "frame_ops.hpp"
#include "result_json.hpp"

namespace pxflow::cli {

// Everything known about one pair once the backend ran.
struct PairRun {
  std::string prev_name, next_name;
  FrameShaping shaping;  // --crop and --bin: how each input became the frame the backend saw
  std::string backend, implementation, device, profile;
  const Params* params = nullptr;
  FrameResult result;
  std::span<const PoiRecord> records;
  OpCounts counts;
  double host_seconds = 0;  // the backend's run(), steady_clock
  std::optional<Backend::DeviceTime> device_time;
};

// The JSON object: what ran (backend, implementation, device), the inputs (prev, next, crop,
// bin), the frame size, profile and params, then the estimate as flow_result_json gives it (the
// records with their status names). No times, no thread count: the bytes depend on the inputs,
// the options that shape the result and the build only (json_document adds the build).
Json pair_json(const PairRun& run);

// Why the flow is 0 when MINCOUNT decided it ("" otherwise).
std::string mincount_note(const PairRun& run);

// "WxH+X+Y" of --crop as the frames were cut ("" without --crop).
std::string crop_text(const FrameShaping& s);

// The picture's caption (--draw): the frame names with the crop and binning, backend, profile.
DrawCaption draw_caption(const PairRun& run);

std::string csv_header();
std::string csv_row(int index, const PairRun& run);

// The multi-line summary of one pair (stdout of `pxflow flow A B`).
std::string pair_summary(const PairRun& run);

// "cpu -> avx512bw", "vulkan -> flow.comp on llvmpipe ...": the backend, what it ran, where.
std::string what_ran(const PairRun& run);
// One line per pair of a sequence.
std::string pair_line(int index, const PairRun& run);

}  // namespace pxflow::cli
