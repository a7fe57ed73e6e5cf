// The limit cases of the fixed corpus (docs/harness.md, "Every backend at its limits"): the
// corners of what each selected backend declares it supports, found from its unsupported()
// predicate, and the corners of SPEC §1's ranges every backend must handle. Every row runs every
// limit case (n/a where its predicate refuses it), so the corpus stays one list of cases that
// shards and merges like the rest.
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

// One limit problem: what edge it is ("largest-square"), the rows whose edge it is (none: one of
// SPEC §1's corners) and its parameters.
struct LimitProbe {
  std::string kind;
  std::vector<std::string> rows;
  Params params;
  std::string what() const;  // "largest-square of gap8-local,gap8-fast"
};

// The probes of `rows` (SPEC §1's corners first, then each row's own), deduplicated by
// parameters (the rows that found the same edge are all named) in a fixed order.
std::vector<LimitProbe> limit_probes(std::span<const LimitRow> rows);

// The probes as corpus cases "limits/<what>", each with seeded random pairs of its size.
std::vector<CheckCase> limit_cases(std::span<const LimitRow> rows, std::uint64_t seed);

// Whether a case is one of limit_cases(), and the entry a row's `limits` list gets for it
// ("limits/largest-square of gap8-local 181x181 S=4 B=8").
bool is_limit_case(const CheckCase& c);
std::string limit_entry(const CheckCase& c);

// The frames a limit case may have at most: a larger accepted square is named in the docs but not
// run (an 8192x8192 pair costs seconds per row); the strips reach the 16384 side limit instead.
inline constexpr std::int64_t kAffordableLimitPixels = std::int64_t{1} << 20;

}  // namespace pxflow
