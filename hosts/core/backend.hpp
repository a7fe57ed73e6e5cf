// The backend interface: what every implementation of the kernel (reference, CPU SIMD, OpenCL,
// Vulkan, GAP8 model) offers to the CLI, the checker and the benchmark. Nothing above this file
// knows a backend by name; they iterate the registry (registry.hpp).
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "frame.hpp"
#include "kernel.hpp"
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

  // Builds what run() needs for problems of these parameters (p valid and supported): the
  // kernels a driver compiles (vulkan: the pipelines of S, each warmed by a dispatch of no work,
  // since lavapipe compiles at the first dispatch). Build time is not the kernel's: run() builds
  // what it lacks before any wait sized by its work, and a caller that limits run()'s time (check's
  // case allowance) calls this first, within an allowance of its own. Throws BackendError.
  virtual void prepare(const Params&) {}

  // Empty when this backend supports a problem of these parameters; otherwise the documented
  // limit it is outside (e.g. a frame too large for the device's local memory). The checker
  // counts such a case "n/a" for this backend.
  virtual std::string unsupported(const Params&) const { return {}; }

  // For a backend that checks itself with code it does not time (vulkan: flow.comp built with
  // and without its shader checks): `timed` false, from create() on, makes run() run the checked
  // code (check, flow, bench's check); true, the code bench times. Returns what the timed code
  // is ("production shader"), or "" when the backend times the code it checks.
  virtual std::string select_timed(bool timed) {
    (void)timed;
    return {};
  }

  // The duration of the last run() by the backend's own clock (OpenCL event profiling, Vulkan
  // timestamps, the GAP8 model's cycles), when it has one. The benchmark reports it beside the
  // host clock and never compares figures of different sources.
  struct DeviceTime {
    std::string source;  // e.g. "opencl-event-profiling", "vulkan-timestamps", "gap8-model-cycles"
    double ns = 0;
    std::optional<double> cycles{};  // when the clock counts cycles
    // When the clock counts instructions instead (QEMU -icount: the m4-qemu row); never
    // reported as cycles.
    std::optional<double> instructions{};
    // A deterministic cycle model (the GAP8 model): one run is the measurement, and the host
    // time is the simulation's speed, never the backend's throughput.
    bool exact = false;
  };
  virtual std::optional<DeviceTime> last_device_time() const { return std::nullopt; }

  // What runs behind the row, for the human output and the report's provenance, read after
  // create(). Empty fields say nothing beyond the row's name and the host CPU.
  struct Description {
    std::string implementation;  // the code that runs: `cpu` -> "avx512bw"
    std::string device;          // e.g. "cpu-haswell-AMD EPYC 7B13 (OpenCL 3.0 PoCL 3.1 ...)"
    std::string driver;          // e.g. "Mesa 22.3.6 (LLVM 15.0.6)", "gap8_model 1a2b3c4d5e6f"
  };
  virtual Description describe() const { return {}; }

  // What kind of device the kernel runs on, as its driver reports it: "cpu" (a driver that runs
  // it on the host's cores: PoCL's pthread device, lavapipe), "gpu", "other"; "" for code on the
  // host CPU or a backend that does not say. The bench's bound of a row follows from it
  // (docs/harness.md, "The bound of every row").
  virtual std::string device_kind() const { return {}; }

  // A bound of the backend's own clock for one frame of these parameters, which the bench puts
  // beside the rows of that clock (the GAP8 model's cycles, QEMU's instructions): what it is, its
  // unit and its figure; nullopt where the bench's own bounds decide (docs/harness.md, "The bound
  // of every row").
  struct DeviceBound {
    std::string what;      // how it is made, for the bench's header and the report
    std::string unit;      // of `per_frame`: "cycles", "instructions"
    double per_frame = 0;  // in `unit`
  };
  virtual std::optional<DeviceBound> device_bound(const Params&) const { return std::nullopt; }
};

// SPEC §6's SAD work of one frame that every bound is made of: every POI searched ((2S+1)^2
// candidates) and refined (8 half steps), 64 bytes each, the feature test left out (364,544
// bytes for px4flow-64).
inline double sad_bytes_per_frame(long pois, int search_radius) {
  const long candidates = (2L * search_radius + 1) * (2L * search_radius + 1);
  return static_cast<double>(pois) * static_cast<double>(candidates + 8) * 64.0;
}

// Where a backend runs, as every result says it: its device (OpenCL, Vulkan, a model, a board),
// or "host" for code on the host CPU. A result whose backend did not run says "".
inline std::string device_or_host(const Backend::Description& d) {
  return d.device.empty() ? "host" : d.device;
}

// One row of the registry.
struct BackendRow {
  std::string name;   // used everywhere: --backend, check lines, bench rows, reports
  std::string needs;  // what it needs to run, for humans ("x86-64 with AVX2", "an OpenCL device")
  // Empty when the backend can run on this machine now; otherwise the one-line reason it cannot.
  std::function<std::string()> probe;
  // Creates a ready backend; throws BackendError with the reason when set-up fails.
  std::function<std::unique_ptr<Backend>(const BackendOptions&)> create;
  // The backend a user gets by default (flow's pictures in the report, accuracy): the first
  // preferred row that can run here, else ref-original (registry.hpp: default_backend()).
  bool preferred = false;
  // Whether the backend has devices that --device chooses among (OpenCL, Vulkan).
  bool has_devices = false;
  // For a row that needs hardware some machines of the same build lack (an ISA extension): true
  // where this machine lacks it. `check --require all` then reports the row skipped (the
  // machine's limit, not the backend's failure); naming the row in --require still requires it.
  std::function<bool()> host_lacks{};
  // The row's counting model: the reference variant whose rules (docs/counting.md) its counts
  // follow whenever it counts (counts.counted). `pxflow check` holds its counts to them
  // (hosts/harness/check/check_counts.hpp); a row that counts without naming one fails there.
  std::optional<RefVariant> counts_like{};
  std::string family{};  // filled in by the registry from the family the row came from
};

// A global command-line option a family adds (e.g. the cpu family's --disable-isa). The CLI
// declares it on every command and calls `apply` before the command runs when it was given.
struct FamilyOption {
  std::string flag;  // "--disable-isa"
  std::string help;
  std::function<void(const std::string&)> apply;  // throws InputError for a bad value
  // May be given more than once (the dut family's --dut): `apply` is called for each value, in
  // command-line order.
  bool repeatable = false;
  std::string value_name = "VALUE";  // what the value is, in --help: "NAME=SPEC", "SECONDS"
  // The value is a file pxflow reads (--m4-firmware): an input of every command, which no output
  // may overwrite (hosts/cli/path_options.hpp).
  bool reads_file = false;
};

// An environment variable a family reads: every --help and man page lists it (ENVIRONMENT).
struct EnvironmentVariable {
  std::string name;  // "PXFLOW_DISABLE"
  std::string help;  // what it does, for the help text
};

// A bound the benchmark puts beside the rows timed by `clock` (the cpu family: the SAD-instruction
// ceiling in TSC cycles): how many times the bound each row's cycles per frame are, the bound
// measured on as many threads as the row was given, so that no row can beat it.
struct BenchBound {
  std::string name;   // what the bound is, e.g. "back-to-back vdbpsadbw zmm on L1 data (...)"
  std::string clock;  // rows whose time source contains this ("tsc") get a ratio
  // Bytes compared per cycle of `clock` by `threads` threads running the loop at once (measured
  // when called: the bench calls it once per thread count it meets).
  std::function<double(int threads)> bytes_per_cycle;
  // The bound's bytes for one frame of `pois` POIs at search radius S.
  std::function<double(long pois, int search_radius)> bytes_per_frame;
};

// What one family contributes: its rows and the optional extensions only it knows about.
// Families are registered by the CMake call pxflow_backend_family() (cmake/).
struct BackendFamily {
  std::string name;  // "cpu", "opencl", ...
  std::vector<BackendRow> rows;
  std::vector<FamilyOption> options;
  std::function<std::optional<BenchBound>()> measure_bench_bound{};  // empty: no bound
  // Checks the environment variables the family reads (the cpu family: PXFLOW_DISABLE); throws
  // InputError for a bad value. The CLI calls it before every command. Empty: nothing to check.
  std::function<void()> check_environment{};
  std::vector<EnvironmentVariable> environment{};  // the variables it reads, for --help
};

}  // namespace pxflow
