// The bound of every timed bench row (docs/harness.md, "The bound of every row"): the SAD work of
// the row's frame at the fastest rate its hardware can do it, in the row's own unit, and the
// fraction of it the row achieved. One place decides which bound a row gets, or why it has none.
#pragma once
#include <functional>
#include <optional>
#include <string>

#include "backend.hpp"
#include "bench.hpp"

namespace pxflow {

// What the bench knows about a row's backend when it bounds the row.
struct BoundInputs {
  // The host's SAD ceiling (the cpu family's BenchBound), or nullptr: none on this machine, or
  // `--no-bound` (then `why_none` says so).
  const BenchBound* host = nullptr;
  std::string why_none;
  // The ceiling's bytes per TSC cycle on `threads` threads (measured when first asked for), and
  // the TSC's rate in Hz (to turn it into time for rows timed in nanoseconds).
  std::function<double(int threads)> host_bytes_per_cycle;
  std::function<double()> tsc_hz;
  bool on_host = false;                        // the backend's code runs on the host CPU
  std::string device_kind;                     // Backend::device_kind()
  std::optional<Backend::DeviceBound> device;  // Backend::device_bound() at the row's point
};

// Sets the row's `bound` (what it is, or "none: why"), `bound_unit`, `bound_per_frame`,
// `bound_fraction` (the bound's figure over the row's, 1 = at the bound) and `bound_ratio` (its
// inverse, the "x bound" of earlier files). A row that was not timed is left as it is.
void set_row_bound(BenchRow& r, const BoundInputs& in);

// Recomputes `bound_fraction` and `bound_ratio` from `bound_per_frame` and the row's own figure
// (bench --processes: a combined row's median changes, its bound does not).
void refresh_bound_fraction(BenchRow& r);

}  // namespace pxflow
