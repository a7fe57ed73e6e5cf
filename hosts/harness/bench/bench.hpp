// pxflow bench: throughput of every backend whose output was just checked, over sweeps of batch
// size, frame size, search radius and threads. Medians of repeated runs; every row names its
// clock; speed-ups only between rows of the same clock.
#pragma once
#include <iosfwd>
#include <nlohmann/json.hpp>  // complete: BenchRow and BenchReport hold Json by value
#include <optional>
#include <string>
#include <vector>

#include "backend.hpp"
#include "interrupt.hpp"
#include "result_fields.hpp"
#include "result_json.hpp"

namespace pxflow {

// How a run's machine looked (machine_state.cpp): what the bench records before and after it, so
// that a reader can tell a quiet run from a disturbed one.
struct MachineState {
  double load_1min = -1;  // /proc/loadavg; -1 where unreadable
  double cpu_mhz = 0;     // the mean of /proc/cpuinfo's "cpu MHz"; 0 where unreadable
  int cpus = 0;
};

// What other processes did while the bench ran, from /proc/stat and /proc/self/stat.
struct MachineLoad {
  MachineState before, after;
  double others_cpu_share =
      -1;                   // of every CPU's time, by processes other than this one; -1: unknown
  double steal_share = -1;  // of every CPU's time, taken by the hypervisor; -1: unknown
  std::string disturbed;    // why the run was disturbed (kDisturbedShare), or empty
};

// One measured configuration.
struct BenchPoint {
  std::string sweep;  // "batch", "size", "radius", "threads" or "custom"
  std::string setting;
  Params params;
  int batch = 1;
  int threads = 0;  // 0 = all cores
};

struct BenchOptions {
  std::vector<std::string> backends;  // empty: all that can run
  std::vector<BenchPoint> points;
  // Seconds of measured samples per point and backend, after the checked run: a minimum, reached
  // whatever the row's speed (unless max_samples stops it first).
  double min_seconds = 0.25;
  int max_samples = 0;  // 0: no cap

  double max_run_seconds = 3.0;  // skip a point whose single run would take longer
  BackendOptions backend_options;
  // Extra runs of each sample's batch, in percent of its runs, timed but not counted as frames:
  // the planted slowdown of the gate's A/B experiment (PXFLOW_BENCH_PLANTED_SLOWDOWN, docs/
  // harness.md "The gate's error rates"). Known work per frame, never a sleep.
  int planted_slowdown_percent = 0;
  bool measure_bound = true;  // false: no bound, no "x bound" (bench --no-bound)
};

// PXFLOW_BENCH_PLANTED_SLOWDOWN's value (0 when unset); throws InputError when it is not a whole
// percent in 1..100.
int planted_slowdown_from_environment();

struct BenchRow {
  std::string backend, sweep, setting, source, note;
  int width = 0, height = 0, search_radius = 0, batch = 0, threads = 0, repeats = 0;
  // What else makes a row's work what it is (pxflow compare pairs rows only where all of it is
  // equal): every parameter (params_json, --set included), the threads asked for (0 = all
  // cores; `threads` is what that was here), and what the backend ran on (describe_backend's
  // line: implementation, device, driver).
  Json params = Json::object();
  int threads_requested = 0;
  std::string device;
  // What was timed where the backend checks other code than it times (Backend::select_timed):
  // "production shader"; empty where it times the code it checked.
  std::string timed_build;
  // The unit of replication is a process (docs/harness.md, "Statistics"): the row's samples come
  // from `processes` processes, `samples_per_process` of them each, and its median and interval
  // are those of the processes' own medians. One process: the samples' median and interval.
  int processes = 1;
  std::vector<double> process_medians_ns_per_frame;
  std::vector<int> samples_per_process;
  long pois_per_frame = 0;
  double median_ns_per_frame = 0, min_ns_per_frame = 0, max_ns_per_frame = 0;
  // The 95 % confidence interval of the median (order statistics: distribution-free), and
  // whether the point is noisy (bench_stats.hpp: is_noisy).
  double median_ci_low_ns = 0, median_ci_high_ns = 0;
  bool noisy = false;
  // Each sample: `runs_per_sample` runs of the batch timed together, in ns per frame; the
  // seconds they took together.
  std::vector<double> samples_ns_per_frame;
  int runs_per_sample = 0;
  double measured_s = 0;
  double frames_per_s = 0, ns_per_poi = 0;
  double cycles_per_frame = 0;        // 0 when the source has no cycle clock
  double instructions_per_frame = 0;  // 0 when the source does not count instructions
  // The row's bound (bench_bound.hpp; docs/harness.md, "The bound of every row"): what it is,
  // or "none: why" for a timed row that has none ("" for a row not timed); its unit
  // ("tsc-cycles", "cycles", "instructions", "ns") and figure per frame; the fraction of it the
  // row achieved (the bound's figure over the row's, 1 = at the bound), and its inverse, the
  // row's figure over the bound's ("x bound"). 0: none.
  std::string bound, bound_unit;
  double bound_per_frame = 0, bound_fraction = 0;
  double bound_ratio = 0;
  double speedup_vs_reference = 0;  // vs ref-original, same point and source; 0 when not measured
  bool exact_clock = false;         // timed by a deterministic device clock (DeviceTime::exact)
};

struct BenchReport {
  // The bound a family offered (BenchBound), or empty: what it is, the clock of the rows it
  // applies to, and its bytes compared per cycle of that clock.
  std::string bound_name, bound_clock;
  double bound_bytes_per_cycle = 0;                      // on one thread
  std::vector<std::pair<int, double>> bound_by_threads;  // (threads, bytes per cycle), measured
  double tsc_hz = 0;  // the TSC's rate, measured when a row timed in ns needs the bound in time
  MachineLoad machine;
  std::vector<BenchRow> rows;        // point by point, backends in registry order
  std::vector<std::string> skipped;  // "backend: reason" lines
  // What each opened backend ran (provenance.hpp: describe_backend), in registry order.
  Json backends = Json::array();
  std::string command;  // the command line that made this report, for its JSON
  int processes = 1;    // the processes whose rows were combined (bench --processes)
  // Which build and machine measured it: null for this process's own (bench_json writes
  // build_provenance() and machine_provenance()); a combined report keeps its processes'.
  Json provenance;
  // False when a signal stopped the bench: `rows` holds every row it measured, the points before
  // the stopped one whole, and `stop` says which signal (the command writes the file, then
  // throws it).
  bool complete = true;
  std::size_t points_done = 0, points_total = 0;
  std::optional<Interrupted> stop;
  std::string failed;  // bench --processes: why a process failed (the report holds those before)
};

// `bench --processes`'s default (docs/harness.md, "Statistics"): with 5 processes on each side,
// pxflow compare's 95 % interval of a ratio is bounded (4 and 4 is the least), and the default
// bench takes about as long as one process did, --min-time being split over them.
inline constexpr int kDefaultProcesses = 5;

// The default sweeps around `base` (the profile with any --set applied).
std::vector<BenchPoint> default_bench_points(const Params& base, const std::string& profile_name);

// The quick subset of the default sweeps (`bench --quick`, `report --quick`): batch <= 256 and
// the frame sizes, no radius or thread sweep; with kQuickMinSeconds of repeats per point.
std::vector<BenchPoint> quick_bench_points(const Params& base, const std::string& profile_name);
constexpr double kQuickMinSeconds = 0.05;

// Every point but the thread sweep's run on `threads` host threads (0 = all cores), as
// `bench --threads N` and `report --threads N` ask.
void set_sweep_threads(std::vector<BenchPoint>& points, int threads);

// Runs every point: prints the backends with what each runs, then one aligned table (a group of
// rows per point, the bound's ratio and the speed-up over ref-original as columns). A signal
// stops it between samples: the report then holds what was measured, marked incomplete.
BenchReport run_bench(const BenchOptions& o, std::ostream& out);

// The table's header and one row's line (a row not timed: its note), as the bench prints them
// point by point and `bench --processes` prints the rows it combined.
std::string bench_header_line(std::size_t name_width);
std::string bench_row_line(const BenchRow& r, std::size_t name_width);
inline constexpr const char* kNoisyNote = "noisy: rerun on a quiet machine";

// The keys of a bench row's JSON object that code reading bench files names (pxflow compare, whose
// own rows use the same keys where they mean the same): the one spelling of each, which
// bench_row_fields() uses too.
namespace bench_key {
inline constexpr const char* kBackend = "backend";
inline constexpr const char* kSweep = "sweep";
inline constexpr const char* kProfile = "profile";
inline constexpr const char* kWidth = "width";
inline constexpr const char* kHeight = "height";
inline constexpr const char* kSearchRadius = "search_radius";
inline constexpr const char* kBatch = "batch";
inline constexpr const char* kThreads = "threads";
inline constexpr const char* kThreadsRequested = "threads_requested";
inline constexpr const char* kDevice = "device";
inline constexpr const char* kParams = "params";
inline constexpr const char* kSource = "source";
inline constexpr const char* kExactClock = "exact_clock";
inline constexpr const char* kProcesses = "processes";
inline constexpr const char* kMedianNs = "median_ns_per_frame";
inline constexpr const char* kSamples = "samples_ns_per_frame";
inline constexpr const char* kProcessMedians = "process_medians_ns_per_frame";
inline constexpr const char* kNote = "note";
}  // namespace bench_key

// A row's fields as the bench's JSON and CSV carry them (bench_json.cpp): the only list of them.
std::span<const ResultField<BenchRow>> bench_row_fields();
Json bench_json(const BenchReport& r);

}  // namespace pxflow
