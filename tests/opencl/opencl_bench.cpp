// pxflow_opencl_bench: batch throughput of the opencl backend against the best CPU backend in
// this build on all cores, at batch 1, 256 and 4096 (docs/opencl.md has the figures). Every
// configuration is checked first (opencl's records must equal the CPU backend's byte for byte);
// only then is it timed. Clocks: wall (steady_clock) around Backend::run for both, the process
// CPU time per pair (core-microseconds, all threads), and the OpenCL event-profiled kernel and
// transfer times of the last opencl run.
//
//   pxflow_opencl_bench [--cpu NAME] [--sizes 64,640] [--batches 1,256,4096] [--seconds S]
//                       [--layout group|item] [--group-size N]   (default: the row's choice)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <thread>
#include <vector>

#include "errors.hpp"
#include "exactness.hpp"
#include "grid.hpp"
#include "opencl_backend.hpp"
#include "registry.hpp"
#include "synthetic.hpp"

namespace pxflow {
namespace {

struct Options {
  std::string cpu;  // empty: "cpu" when it can run here, else ref-original on every core
  std::vector<int> sizes = {64, 640};
  std::vector<int> batches = {1, 256, 4096};
  double seconds = 1.0;  // minimum timed time per measurement
  OpenclTuning tuning;
};

// px4flow-64 for 64, else the large-frame profile of the tests: S=7, B=32 at 640x480.
Params params_for(int size) {
  if (size == 64) return profile("px4flow-64");
  Params p;
  p.width = size;
  p.height = size * 3 / 4;
  p.search_radius = 7;
  p.blocks = 32;
  return p;
}

// A batch of `n` views onto a pool of at most 64 distinct seeded random pairs (so 4096 large
// frames do not need gigabytes of host memory; the device still receives every pair).
struct Batch {
  std::vector<OwnedPair> pool;
  std::vector<FramePair> pairs;
};

Batch make_batch(const Params& p, int n) {
  Batch b;
  for (int s = 0; s < std::min(n, 64); ++s)
    b.pool.push_back(random_pair(p.width, p.height, p.search_radius, 5000 + s));
  for (int i = 0; i < n; ++i) b.pairs.push_back(b.pool[i % b.pool.size()].view());
  return b;
}

// Runs a batch on a backend; ref-* rows are single-threaded, so they get one instance per core
// and a slice of the batch each, like the CPU rows' own thread pools.
class CpuRunner {
 public:
  explicit CpuRunner(const std::string& name) : name_(name) {
    const BackendRow& row = find_backend(name);
    if (const std::string why = row.probe(); !why.empty())
      throw InputError(name + " cannot run here: " + why);
    const bool scalar = name.rfind("ref-", 0) == 0;
    const int copies = scalar ? std::max(1u, std::thread::hardware_concurrency()) : 1;
    for (int i = 0; i < copies; ++i) backends_.push_back(row.create({}));
  }

  std::string label() const {
    return name_ + (backends_.size() > 1 ? " x" + std::to_string(backends_.size()) + " threads"
                                         : " (all cores)");
  }

  void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out) {
    const std::size_t per_pair = poi_count(p);
    const std::size_t slice = (pairs.size() + backends_.size() - 1) / backends_.size();
    std::vector<std::thread> workers;
    for (std::size_t t = 0; t < backends_.size() && t * slice < pairs.size(); ++t) {
      const std::size_t first = t * slice, n = std::min(slice, pairs.size() - first);
      workers.emplace_back([&, t, first, n] {
        OpCounts counts;
        backends_[t]->run(pairs.subspan(first, n), p, out.subspan(first * per_pair, n * per_pair),
                          counts);
      });
    }
    for (auto& w : workers) w.join();
  }

 private:
  std::string name_;
  std::vector<std::unique_ptr<Backend>> backends_;
};

// Wall and process CPU seconds per call of `f` (CPU time sums every thread: a load-independent
// measure of work on a shared machine), means over as many calls as fit in `min_seconds`.
struct Cost {
  double wall = 0;
  double cpu = 0;
};

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <class F>
Cost cost_per_run(F&& f, double min_seconds) {
  using clock = std::chrono::steady_clock;
  f();  // warm-up: first-use costs (page faults, PoCL's kernel specialization) are not timed
  int runs = 0;
  const auto start = clock::now();
  const double cpu_start = process_cpu_seconds();
  double elapsed = 0;
  while (runs < 2 || elapsed < min_seconds) {
    f();
    ++runs;
    elapsed = std::chrono::duration<double>(clock::now() - start).count();
  }
  return {elapsed / runs, (process_cpu_seconds() - cpu_start) / runs};
}

void bench_one(const Options& o, CpuRunner& cpu, OpenclBackend& ocl, int size, int batch) {
  const Params p = params_for(size);
  const Batch b = make_batch(p, batch);
  const std::size_t records = b.pairs.size() * poi_count(p);
  std::vector<PoiRecord> expected(records), got = sentinel_records(records);
  OpCounts counts;
  cpu.run(b.pairs, p, expected);
  ocl.run(b.pairs, p, got, counts);
  if (std::memcmp(expected.data(), got.data(), records * sizeof(PoiRecord)) != 0)
    throw BackendError("opencl records differ from " + cpu.label() + " at " +
                       std::to_string(p.width) + "x" + std::to_string(p.height) + ", batch " +
                       std::to_string(batch) + ": not timed");

  const Cost c = cost_per_run([&] { cpu.run(b.pairs, p, expected); }, o.seconds);
  const Cost g = cost_per_run([&] { ocl.run(b.pairs, p, got, counts); }, o.seconds);
  const OpenclTiming& dev = ocl.last_timing();
  std::printf("%4dx%-4d %5d  %11.0f %11.0f %7.2f  %9.1f %9.1f %7.2f  %10.3f %9.3f %8.3f %3d\n",
              p.width, p.height, batch, batch / c.wall, batch / g.wall, c.wall / g.wall,
              1e6 * c.cpu / batch, 1e6 * g.cpu / batch, c.cpu / g.cpu, 1e3 * g.wall,
              1e3 * dev.kernel_seconds, 1e3 * dev.transfer_seconds, dev.launches);
}

std::vector<int> int_list(const std::string& text) {
  std::vector<int> out;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    out.push_back(parse_int(text.substr(at, comma - at), "list item", 1, 1 << 20));
    at = comma + 1;
  }
  return out;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string key = argv[i];
    if (i + 1 >= argc) throw InputError(key + " needs a value");
    const std::string value = argv[++i];
    if (key == "--cpu")
      o.cpu = value;
    else if (key == "--sizes")
      o.sizes = int_list(value);
    else if (key == "--batches")
      o.batches = int_list(value);
    else if (key == "--seconds")
      o.seconds = parse_int(value, key, 0, 3600);
    else if (key == "--group-size")
      o.tuning.group_size = parse_int(value, key, 1, 4096);
    else if (key == "--layout" && (value == "group" || value == "item"))
      o.tuning.layout = value == "group" ? OpenclLayout::kGroupPerPoi : OpenclLayout::kItemPerPoi;
    else
      throw InputError("unknown option " + key + " " + value);
  }
  if (o.cpu.empty()) {
    const auto& rows = backend_rows();
    const bool has_cpu = std::any_of(rows.begin(), rows.end(), [](const BackendRow& r) {
      return r.name == "cpu" && r.probe().empty();
    });
    o.cpu = has_cpu ? "cpu" : "ref-original";
  }
  return o;
}

int run(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // rows appear as they are measured
  const Options o = parse(argc, argv);
  CpuRunner cpu(o.cpu);
  OpenclBackend ocl({}, o.tuning);
  std::printf("cpu: %s; opencl: %s, %s, work-group size %zu; wall clock, mean of runs >= %.0f s\n",
              cpu.label().c_str(), ocl.device_name().c_str(),
              ocl.layout() == OpenclLayout::kGroupPerPoi ? "group-per-poi" : "item-per-poi",
              ocl.group_size(), o.seconds);
  std::printf("%-9s %5s  %11s %11s %7s  %9s %9s %7s  %10s %9s %8s %3s\n", "frame", "batch",
              "cpu pair/s", "ocl pair/s", "ocl/cpu", "cpu us/pr", "ocl us/pr", "ocl/cpu",
              "ocl ms/run", "kernel ms", "xfer ms", "launches");
  for (int size : o.sizes)
    for (int batch : o.batches) bench_one(o, cpu, ocl, size, batch);
  return 0;
}

}  // namespace
}  // namespace pxflow

int main(int argc, char** argv) {
  try {
    return pxflow::run(argc, argv);
  } catch (const pxflow::InputError& e) {
    std::fprintf(stderr, "pxflow_opencl_bench: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pxflow_opencl_bench: failed: %s\n", e.what());
    return 1;
  }
}
