// Shrinking a mismatch to a minimal reproducer: one frame pair cropped to the failing POI's read
// window (prev's 8x8 block, next's search area), then simplified pixel by pixel region while the
// backend still differs from the reference in the same stage. The backend is only reached through
// a runner, so that it may run in this process or another one.
#pragma once
#include <chrono>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mismatch_stage.hpp"
#include "params.hpp"
#include "record.hpp"
#include "synthetic.hpp"

namespace pxflow {

// A backend's records for a batch, or why it produced none (an exception, an unsupported size).
// A runner reports failures here; only an interrupt (Ctrl-C) leaves it as an exception.
struct RunOutcome {
  std::vector<PoiRecord> records;
  std::string error;  // non-empty: no records
};
using PairRunner = std::function<RunOutcome(std::span<const FramePair>, const Params&)>;

// Bounds on the backend runs one shrink may spend (each candidate is one run of one pair).
struct ShrinkLimits {
  double seconds = 30;
  int max_runs = 400;
};

struct Reproducer {
  OwnedPair pair;              // a copy of its name: "<the failing pair's name>, shrunk"
  Params params;               // width and height are the pair's
  std::size_t poi = 0;         // the first POI that differs
  Stage stage = Stage::kSame;  // the stage it differs in: the failing pair's
  std::string what;            // stage_words() on the reproducer
  int runs = 0;                // backend runs spent
  bool cropped = false;        // false: the crop did not fail, so the frame kept its size
};

// Shrinks `pair` (on which `run` differs from ref-original at POI `poi` in some stage) within
// `limits`. Nothing when the difference could not be reproduced even on the pair as given.
std::optional<Reproducer> shrink_mismatch(const OwnedPair& pair, const Params& p, std::size_t poi,
                                          const PairRunner& run, const ShrinkLimits& limits);

}  // namespace pxflow
