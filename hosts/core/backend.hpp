// The backend interface: what every implementation of the kernel (reference, CPU SIMD, OpenCL,
// Vulkan, GAP8 model) offers to the CLI, the checker and the benchmark. Nothing above this file
// knows a backend by name; they iterate the registry (registry.hpp).
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "frame.hpp"
#include "params.hpp"
#include "record.hpp"

namespace pxflow {

// Run-time choices a user can make for a backend; each backend reads what applies to it.
struct BackendOptions {
  int threads = 0;     // host worker threads (CPU backends, GAP8 model); 0 = all cores
  std::string device;  // device index or name substring (OpenCL, Vulkan); empty = default
};

class Backend {
 public:
  virtual ~Backend() = default;

  // The batch entry point. Runs every pair of `pairs` (all of the size p.width x p.height, p
  // valid) and writes poi_count(p) records per pair into `out`, pair after pair. Either every
  // record is written or a BackendError is thrown: no partial results. Work is added to `counts`
  // by backends that count it (they set counts.counted).
  virtual void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
                   OpCounts& counts) = 0;

  // Empty when this backend supports a problem of these parameters; otherwise the documented
  // limit it is outside (e.g. a frame too large for the device's local memory). The checker
  // counts such a case "n/a" for this backend.
  virtual std::string unsupported(const Params&) const { return {}; }

  // The duration of the last run() by the backend's own clock (OpenCL event profiling, Vulkan
  // timestamps, the GAP8 model's cycles), when it has one. The benchmark reports it beside the
  // host clock and never compares figures of different sources.
  struct DeviceTime {
    std::string source;  // e.g. "opencl-events", "vulkan-timestamps", "gap8-model-cycles"
    double ns = 0;
    std::optional<double> cycles;  // when the clock counts cycles
  };
  virtual std::optional<DeviceTime> last_device_time() const { return std::nullopt; }
};

// One row of the registry.
struct BackendRow {
  std::string name;   // used everywhere: --backend, check lines, bench rows, reports
  std::string needs;  // what it needs to run, for humans ("x86-64 with AVX2", "an OpenCL device")
  // Empty when the backend can run on this machine now; otherwise the one-line reason it cannot.
  std::function<std::string()> probe;
  // Creates a ready backend; throws BackendError with the reason when set-up fails.
  std::function<std::unique_ptr<Backend>(const BackendOptions&)> create;
};

}  // namespace pxflow
