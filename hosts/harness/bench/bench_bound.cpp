#include "bench_bound.hpp"

#include <thread>

#include "number_text.hpp"

namespace pxflow {
namespace {

struct RowBound {
  std::string what;      // what the bound is, or "none: why"
  std::string unit;      // of per_frame
  double per_frame = 0;  // 0: none
};

RowBound none(const std::string& why) { return {"none: " + why, "", 0}; }

bool host_clock_row(const BenchRow& r) { return r.source.rfind("host-", 0) == 0; }

// Code on the host CPU: the SAD ceiling in TSC cycles, on as many threads as the row was given.
RowBound host_bound(const BenchRow& r, const BoundInputs& in, double bytes) {
  if (!in.host) return none(in.why_none);
  if (r.cycles_per_frame <= 0 || r.source.find(in.host->clock) == std::string::npos)
    return none("the host bound is in " + in.host->clock + " cycles, which this row's clock (" +
                r.source + ") does not count");
  return {in.host->name + ", on " + std::to_string(r.threads) + " threads", "tsc-cycles",
          bytes / in.host_bytes_per_cycle(r.threads)};
}

// A driver that runs the kernel on the host's cores (PoCL's pthread device, lavapipe): the same
// ceiling on all the cores, which such a driver's thread pool uses, turned into nanoseconds by
// the TSC's rate; for its own clock's rows and the host's end-to-end time alike.
RowBound cpu_device_bound(const BoundInputs& in, double bytes) {
  if (!in.host) return none(in.why_none);
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  const double bytes_per_s = in.host_bytes_per_cycle(cores) * in.tsc_hz();
  if (bytes_per_s <= 0) return none("the host's TSC rate could not be measured");
  return {in.host->name + ", on all " + std::to_string(cores) +
              " cores (the device is the host CPU), at the TSC's " +
              formatted("%.0f", in.tsc_hz() / 1e6) + " MHz",
          "ns", bytes / bytes_per_s * 1e9};
}

RowBound choose(const BenchRow& r, const BoundInputs& in, double bytes) {
  if (in.device && !host_clock_row(r)) {
    if (in.device->per_frame <= 0) return none(in.device->what);
    return {in.device->what, in.device->unit, in.device->per_frame};
  }
  if (in.on_host) return host_bound(r, in, bytes);
  if (in.device_kind == "cpu") return cpu_device_bound(in, bytes);
  if (in.device_kind == "gpu")
    return none(
        "a GPU: its paper bound (compute units x clock x SAD lanes) needs lanes per compute "
        "unit, which neither OpenCL nor Vulkan reports (docs/harness.md, \"The bound of every "
        "row\")");
  return none("a device with no documented figures" +
              (in.device_kind.empty() ? std::string() : " (device type " + in.device_kind + ")"));
}

// The row's figure per frame in the unit of its bound ("cycles", "tsc-cycles", "instructions",
// "ns"); 0 when the row lacks it.
double row_figure(const BenchRow& r, const std::string& unit) {
  if (unit == "cycles" || unit == "tsc-cycles") return r.cycles_per_frame;
  if (unit == "instructions") return r.instructions_per_frame;
  if (unit == "ns") return r.median_ns_per_frame;
  return 0;
}

}  // namespace

void refresh_bound_fraction(BenchRow& r) {
  r.bound_fraction = r.bound_ratio = 0;
  const double figure = row_figure(r, r.bound_unit);
  if (r.bound_per_frame <= 0 || figure <= 0) return;
  r.bound_fraction = r.bound_per_frame / figure;
  r.bound_ratio = figure / r.bound_per_frame;
}

void set_row_bound(BenchRow& r, const BoundInputs& in) {
  if (r.samples_ns_per_frame.empty()) return;  // not timed: its note says why
  const RowBound b = choose(r, in, sad_bytes_per_frame(r.pois_per_frame, r.search_radius));
  r.bound = b.what;
  r.bound_unit = b.unit;
  r.bound_per_frame = b.per_frame;
  refresh_bound_fraction(r);
  if (r.bound_per_frame > 0 && r.bound_fraction <= 0) {  // a bound the row cannot be held to
    r.bound = "none: the row has no figure in " + b.unit + " (" + b.what + ")";
    r.bound_unit.clear();
    r.bound_per_frame = 0;
  }
}

}  // namespace pxflow
