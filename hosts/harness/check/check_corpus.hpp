// The corpus `pxflow check` runs every backend on: real frames (opencv-doc images and videos,
// 64x64 binned like the PX4FLOW camera and at full size), synthetic motion made with OpenCV,
// seeded random pairs and hostile patterns, at px4flow-64, px4flow-head and larger frames.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "params.hpp"
#include "sample_data.hpp"
#include "synthetic.hpp"

namespace pxflow {

// One batch of pairs sharing parameters: what a backend's run() gets in one call.
struct CheckCase {
  std::string name;     // e.g. "real/64x64", "random/px4flow-head"
  std::string setting;  // the parameter set, e.g. "px4flow-64", "320x240 S=7 B=16"
  Params params;
  std::vector<OwnedPair> pairs;  // each pair's name says where it came from (and its seed)
  // The rows whose case it is (a row's own limit cases); empty: every row's. A row runs only its
  // cases, so that what it runs never depends on the other rows selected.
  std::vector<std::string> rows = {};
  bool for_row(const std::string& row) const;
};

// The version of what build_check_corpus() and a fuzz campaign's batches contain. Raise it with
// every change to the cases, their order, their pairs or their parameters: check files record it
// and `pxflow merge` refuses shards of different versions.
inline constexpr int kCheckCorpusVersion = 3;  // 2: the limit cases; 3: a row's own, the sweep

// `pxflow check --profile NAME --set KEY=VALUE ...`: the parameters the corpus runs at instead of
// its own. Each setting starts from the profile (none given: from its own values), then the sets
// apply in order; every case keeps its frame size and its pairs are made for the new parameters.
// The limit cases are the rows' own limits and are never overridden.
struct ParamOverride {
  std::string profile;            // empty: each setting's own parameters
  std::vector<std::string> sets;  // KEY=VALUE; never width or height

  bool empty() const { return profile.empty() && sets.empty(); }
  bool operator==(const ParamOverride&) const = default;
  // " --profile px4flow-head --set search_radius=20" (the command line's words), or "".
  std::string options() const;
  // Throws InputError for what no setting could run: an unknown profile or key, a malformed
  // KEY=VALUE, width/height, gyro_comp=1, a value outside SPEC §1's range.
  void check() const;
  // `p` overridden, or the reason it is not valid at the override (e.g. the frame is too small
  // for the radius).
  std::optional<Params> apply(const Params& p, std::string* why_not = nullptr) const;
};

struct CorpusOptions {
  ParamOverride params;
  std::uint64_t seed = 1;
  std::string data_dir = kSampleDataDir;
  bool real = true;  // false: generated inputs only (no files needed)
  // Only the limit cases (check_limits.hpp): CI's sanitizer stage runs them alone.
  bool limits_only = false;
};

// The fixed corpus. Throws InputError when a real frame cannot be read (say which file and that
// ci/install-deps.sh installs opencv-doc).
// With o.params, the settings not valid at the override are left out, each named with its
// reason in `dropped` (when given).
std::vector<CheckCase> build_check_corpus(const CorpusOptions& o,
                                          std::vector<std::string>* dropped = nullptr);

// A fuzz batch: `count` random pairs with seeds first_seed.., at the given parameters.
CheckCase fuzz_case(const std::string& setting, const Params& p, std::uint64_t first_seed,
                    int count);

// The larger parameter sets the corpus uses beside the two profiles, overridden by `o` (those
// not valid at the override left out, named in `dropped`).
std::vector<std::pair<std::string, Params>> check_settings(
    const ParamOverride& o = {}, std::vector<std::string>* dropped = nullptr);

}  // namespace pxflow
