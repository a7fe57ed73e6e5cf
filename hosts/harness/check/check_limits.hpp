// The limit cases of the fixed corpus (docs/check-corpus.md, "Every row at its own edges"): the
// corners of what each selected backend declares it supports, found from its unsupported()
// predicate, with a sweep of every search radius it accepts (check_radius_sweep.hpp), and the
// corners of SPEC §1's ranges every backend must handle. A row's own edges are its cases alone
// (CheckCase::rows); SPEC's corners are every row's (n/a where its predicate refuses one). So the
// cases a row runs never depend on which other rows are selected, and the corpus stays one list
// of cases that shards and merges like the rest.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "check_corpus.hpp"
#include "params.hpp"

namespace pxflow {

// A selected row's predicate, as Backend::unsupported(): empty when the row accepts the problem.
// Taken as a function so that a row run in another process answers through the same type.
struct LimitRow {
  std::string name;
  std::function<std::string(const Params&)> unsupported;
};

// The largest value v in [lo, hi] for which accepts(v) holds, given that accepts(lo) does and
// that acceptance is monotone (a larger frame, radius or grid never needs less): exact, the
// result is accepted and result + 1 (when <= hi) refused. Empty when accepts(lo) does not hold.
std::optional<int> largest_accepted(int lo, int hi, const std::function<bool(int)>& accepts);

// One limit problem: what edge it is ("largest-square"), the rows whose edge it is, whether it is
// one of SPEC §1's corners (every row's) and its parameters. A radius-sweep step has planted
// pairs (check_radius_sweep.hpp), `sweep_pairs` of them; every other probe random ones.
struct LimitProbe {
  std::string kind;
  std::vector<std::string> rows;
  Params params;
  bool every_row = false;
  int sweep_pairs = 0;
  std::string what() const;  // "largest-square of gap8-local,gap8-fast"
};

// The probes of `rows` (SPEC §1's corners first, then each row's own), deduplicated by
// parameters (the rows that found the same edge are all named) in a fixed order.
std::vector<LimitProbe> limit_probes(std::span<const LimitRow> rows);

// The probes as corpus cases "limits/<kind>" for the probe's rows (none: every row), each with
// pairs seeded from `seed` and its own parameters (never from its place in the list).
std::vector<CheckCase> limit_cases(std::span<const LimitRow> rows, std::uint64_t seed);

// Whether a case is one of limit_cases(), and the entry `row`'s `limits` list gets for it:
// "limits/hist-filter-off 64x64 S=4 B=8" for SPEC's corners, "limits/largest-square of gap8-local
// 152x152 S=4 B=8" for the row's own edges (its name alone, whatever other rows share the case).
bool is_limit_case(const CheckCase& c);
std::string limit_entry(const CheckCase& c, const std::string& row);

// The frames a limit case may have at most: a larger accepted square is named in the docs but not
// run (an 8192x8192 pair costs seconds per row); the strips reach the 16384 side limit instead.
inline constexpr std::int64_t kAffordableLimitPixels = std::int64_t{1} << 20;
// The radius sweep's frames at most (512x512): below the real frames' 768x576, so that the sweep
// asks no device for larger buffers than the rest of the corpus does (docs/PORTING.md).
inline constexpr std::int64_t kSweepPixels = std::int64_t{1} << 18;

}  // namespace pxflow
