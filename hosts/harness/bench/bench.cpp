#include "bench.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <numeric>
#include <optional>
#include <ostream>
#include <set>
#include <thread>
#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

#include "bench_bound.hpp"
#include "bench_stats.hpp"
#include "counted.hpp"
#include "errors.hpp"
#include "exactness.hpp"
#include "grid.hpp"
#include "interrupt.hpp"
#include "machine_state.hpp"
#include "number_text.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "registry.hpp"
#include "synthetic.hpp"

namespace pxflow {
namespace {

constexpr int kDistinctPairs = 16;  // a batch cycles through these, so memory stays small
// Pairs an exact-clock backend simulates for a sweep point whose whole batch would take too long.
constexpr int kReducedBatch = 4;

std::uint64_t tsc_now() {
#if defined(__x86_64__) || defined(__i386__)
  return __rdtsc();
#else
  return 0;
#endif
}
constexpr bool kHasTsc =
#if defined(__x86_64__) || defined(__i386__)
    true;
#else
    false;
#endif

// The TSC's rate: its ticks over 50 ms of the steady clock (an invariant TSC ticks at one rate
// whatever the cores' clocks do), to turn a bound in TSC cycles into time.
double measure_tsc_hz() {
  if (!kHasTsc) return 0;
  const auto t0 = std::chrono::steady_clock::now();
  const std::uint64_t c0 = tsc_now();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const std::uint64_t c1 = tsc_now();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return static_cast<double>(c1 - c0) / s;
}

// Repeat r times the batch starting at pair r % kDistinctPairs, so that even batch 1 sees a new
// frame each time (as a camera would): timing one frame over and over lets the branch predictor
// learn its data and flatters scalar code by 2x here.
struct Inputs {
  std::vector<OwnedPair> owned;
  std::vector<FramePair> ring;  // batch + kDistinctPairs - 1 views cycling over `owned`
  int batch = 0;
  std::span<const FramePair> batch_for(int repeat) const {
    return std::span(ring).subspan(static_cast<std::size_t>(repeat % kDistinctPairs),
                                   static_cast<std::size_t>(batch));
  }
};

Inputs make_inputs(const Params& p, int batch) {
  Inputs in;
  in.batch = batch;
  for (int n = 0; n < kDistinctPairs; ++n)
    in.owned.push_back(shifted_texture_pair(p.width, p.height, p.search_radius,
                                            0xBE7C4 + static_cast<std::uint64_t>(n)));
  for (int n = 0; n < batch + kDistinctPairs - 1; ++n)
    in.ring.push_back(in.owned[n % kDistinctPairs].view());
  return in;
}

// A point's samples: at least kMinSamples, each of enough runs that about kTargetSamples fill
// --min-time (docs/harness.md, "Statistics").
constexpr int kMinSamples = 5;
constexpr int kTargetSamples = 20;

std::string point_label(const BenchPoint& pt) {
  return pt.setting + " " + std::to_string(pt.params.width) + "x" +
         std::to_string(pt.params.height) + " S=" + std::to_string(pt.params.search_radius) +
         " batch=" + std::to_string(pt.batch) +
         " threads=" + (pt.threads ? std::to_string(pt.threads) : "all");
}

// The table's columns: name, width, and whether the values are right-aligned (numbers).
struct Column {
  const char* name;
  int width;
};
constexpr Column kColumns[] = {{"clock", 22},       {"ns/frame", 12}, {"95% CI of median", 23},
                               {"frames/s", 11},    {"ns/POI", 9},    {"cycles/frame", 13},
                               {"bound/frame", 18}, {"of bound", 8},  {"vs ref", 8}};

std::string pad_name(const std::string& name, std::size_t width) {
  return name + std::string(name.size() < width ? width - name.size() : 0, ' ');
}

class Bench {
 public:
  Bench(const BenchOptions& o, std::ostream& out, std::size_t name_width,
        std::optional<BenchBound> bound)
      : o_(o), out_(out), name_width_(name_width), bound_(std::move(bound)) {}

  // The bound's bytes per cycle on `threads` threads, measured the first time it is asked for.
  double bound_bytes_per_cycle(int threads, BenchReport& report) {
    for (const auto& [t, bpc] : report.bound_by_threads)
      if (t == threads) return bpc;
    const double bpc = bound_->bytes_per_cycle(threads);
    report.bound_by_threads.push_back({threads, bpc});
    return bpc;
  }

  // Opens every row once (all cores) before the first point, so that the table is preceded by
  // what each backend runs and on which device.
  void open_all(std::span<const BackendRow* const> rows, BenchReport& report) {
    for (const BackendRow* row : rows) {
      Backend* b = backend_for(*row, 0, report);
      if (!b) continue;
      Json d = describe_backend(row->name, *b);
      const std::string line = description_line(d);
      described_[row->name] = line;
      if (b->describe().device.empty()) on_host_.insert(row->name);
      out_ << "  " << pad(row->name) << "  " << (line.empty() ? "as named, on the host CPU" : line)
           << "\n";
      report.backends.push_back(std::move(d));
    }
  }

  void print_header() { out_ << "\n" << bench_header_line(name_width_) << "\n"; }

  // One backend at one point: checked first, then timed by its exact clock or by repeats.
  void measure(const BackendRow& row, const BenchPoint& pt, const Inputs& in,
               const std::vector<PoiRecord>& expected, BenchReport& report) {
    Backend* b = backend_for(row, pt.threads, report);
    if (!b) return;
    BenchRow base = row_for(row.name, pt);
    base.device = described_[row.name];
    if (std::string why = b->unsupported(pt.params); !why.empty())
      return note(base, "n/a: " + why, report);
    device_bound_ = b->device_bound(pt.params);
    device_kind_ = b->device_kind();
    const SimulatedBatch sim = simulated_batch(row.name, pt);
    if (!sim.not_run.empty()) return note(base, sim.not_run, report);
    base.batch = sim.batch;
    b->select_timed(false);
    const std::optional<double> checked =
        checked_run(*b, pt, in, expected, sim.batch, base, report);
    if (!checked) return;
    if (const auto d = b->last_device_time(); d && d->exact)
      return emit_exact_clock(*d, *checked, sim, base, report);
    // A backend that times other code than it checked (Backend::select_timed): one run of that
    // code, as warm-up, measures a run instead.
    base.timed_build = b->select_timed(true);
    const double first = base.timed_build.empty() ? *checked : one_run(*b, pt, in);
    if (first > o_.max_run_seconds)
      return note(base, "not timed: one run takes " + std::to_string(first) + " s", report);
    emit_samples(repeat_runs(*b, pt, in, first), base, report);
  }

 private:
  // The pairs a simulated backend runs at a point, or why it is not run there.
  struct SimulatedBatch {
    int batch = 0;
    std::string reduced;  // the note of a batch cut to kReducedBatch pairs
    std::string not_run;  // the note of a point left out
  };

  // A simulated backend's run of a large batch is minutes of host time: from the speed of its
  // last point, a run that would take longer than max_run_seconds is left out of the batch
  // sweep, and said so; the other sweeps (frame size, radius, threads) take the model's cycles
  // from the first kReducedBatch pairs instead, so that every sweep has its figure.
  SimulatedBatch simulated_batch(const std::string& backend, const BenchPoint& pt) const {
    const auto it = sim_pairs_per_s_.find(backend);
    if (it == sim_pairs_per_s_.end()) return {pt.batch, "", ""};
    const double estimate = pt.batch / it->second;
    if (estimate <= o_.max_run_seconds) return {pt.batch, "", ""};
    char why[240];
    if (pt.sweep == "batch" || pt.sweep == "custom") {  // the batch is what is asked for
      std::snprintf(why, sizeof why,
                    "not run: simulating %s would take about %.0f s (%.1f pairs/s); "
                    "measure it with --backends %s --batch %d",
                    counted(pt.batch, "pair").c_str(), estimate, it->second, backend.c_str(),
                    pt.batch);
      return {pt.batch, "", why};
    }
    const int batch = std::min(pt.batch, kReducedBatch);
    std::snprintf(why, sizeof why,
                  "device count of the first %s (the point's %d would take about %.0f s to "
                  "simulate)",
                  counted(batch, "pair").c_str(), pt.batch, estimate);
    return {batch, why, ""};
  }

  // Warm-up and check in one: the first run of `batch` pairs, whose records must equal
  // ref-original's. Its seconds, or nothing when the row was noted as failed or different.
  std::optional<double> checked_run(Backend& b, const BenchPoint& pt, const Inputs& in,
                                    const std::vector<PoiRecord>& expected, int batch,
                                    const BenchRow& base, BenchReport& report) {
    const std::span<const FramePair> pairs = in.batch_for(0).first(static_cast<std::size_t>(batch));
    const std::span<const PoiRecord> want =
        std::span(expected).first(poi_count(pt.params) * static_cast<std::size_t>(batch));
    std::vector<PoiRecord> got = sentinel_records(want.size());
    OpCounts counts;
    const auto w0 = std::chrono::steady_clock::now();
    try {
      b.run(pairs, pt.params, got, counts);
    } catch (const Interrupted&) {
      throw;  // Ctrl-C inside a backend: the run stops, the point did not fail
    } catch (const std::exception& e) {
      note(base, std::string("failed: ") + e.what(), report);
      return std::nullopt;
    }
    const double first = seconds_since(w0);
    if (std::memcmp(got.data(), want.data(), want.size_bytes()) != 0) {
      note(base, "not timed: records differ from ref-original (run pxflow check)", report);
      return std::nullopt;
    }
    return first;
  }

  // The seconds of one run of the batch (its records unchecked).
  static double one_run(Backend& b, const BenchPoint& pt, const Inputs& in) {
    std::vector<PoiRecord> got(poi_count(pt.params) * static_cast<std::size_t>(pt.batch));
    OpCounts counts;
    const auto w0 = std::chrono::steady_clock::now();
    b.run(in.batch_for(0), pt.params, got, counts);
    return seconds_since(w0);
  }

  // Timed by its exact clock from the checked run; the host's time is simulation speed.
  void emit_exact_clock(const Backend::DeviceTime& d, double first, const SimulatedBatch& sim,
                        const BenchRow& base, BenchReport& report) {
    BenchRow dev = base;
    dev.source = d.source;
    dev.exact_clock = true;
    fill(dev, {d.ns / sim.batch}, 1, d.cycles ? *d.cycles / sim.batch : 0);
    if (d.instructions) dev.instructions_per_frame = *d.instructions / sim.batch;
    char speed[128];
    std::snprintf(speed, sizeof speed, "one checked run; host simulation %.1f pairs/s",
                  sim.batch / first);
    dev.note = speed + (sim.reduced.empty() ? "" : "; " + sim.reduced);
    sim_pairs_per_s_[base.backend] = sim.batch / first;
    emit(dev, report);
  }

  // Per-frame figures of the samples: the host's, and the device clock's when it has one.
  struct Samples {
    std::vector<double> host_ns, tsc, device_ns, device_cycles;
    std::string device_source;
    int runs = 1;  // runs of the batch per sample
    double measured_s = 0;
  };

  // Samples of `runs` runs each, calibrated from the checked run's `first` seconds, until
  // min_seconds of samples are measured (and kMinSamples taken), or max_samples; run r starts at
  // pair r.
  Samples repeat_runs(Backend& b, const BenchPoint& pt, const Inputs& in, double first) const {
    Samples s;
    s.runs = static_cast<int>(
        std::clamp(o_.min_seconds / kTargetSamples / std::max(first, 1e-9), 1.0, 1e6));
    // A planted slowdown of P % runs P % more batches than it counts: the runs of a sample are
    // rounded up to a multiple of 100 / gcd(P, 100), so that every sample has exactly P % more.
    int extra = 0;
    if (const int p = o_.planted_slowdown_percent; p > 0) {
      const int unit = 100 / std::gcd(p, 100);
      s.runs = (s.runs + unit - 1) / unit * unit;
      extra = s.runs * p / 100;
    }
    std::vector<PoiRecord> got(poi_count(pt.params) * static_cast<std::size_t>(pt.batch));
    OpCounts counts;
    const double frames = static_cast<double>(s.runs) * pt.batch;
    for (int rep = 1; s.host_ns.size() < static_cast<std::size_t>(kMinSamples) ||
                      s.measured_s < o_.min_seconds;) {
      if (o_.max_samples > 0 && s.host_ns.size() >= static_cast<std::size_t>(o_.max_samples)) break;
      stop_if_interrupted("a bench point's samples");
      double device_ns = 0, device_cycles = 0;
      bool cycles = false;
      const std::uint64_t c0 = tsc_now();
      const auto t0 = std::chrono::steady_clock::now();
      for (int k = 0; k < s.runs + extra; ++k, ++rep) {
        b.run(in.batch_for(rep), pt.params, got, counts);
        if (auto d = b.last_device_time()) {
          s.device_source = d->source;
          device_ns += d->ns;
          if (d->cycles) device_cycles += *d->cycles, cycles = true;
        }
      }
      const double seconds = seconds_since(t0);
      s.tsc.push_back(static_cast<double>(tsc_now() - c0) / frames);
      s.measured_s += seconds;
      s.host_ns.push_back(seconds * 1e9 / frames);
      if (!s.device_source.empty()) s.device_ns.push_back(device_ns / frames);
      if (cycles) s.device_cycles.push_back(device_cycles / frames);
    }
    return s;
  }

  void emit_samples(const Samples& s, const BenchRow& base, BenchReport& report) {
    BenchRow host = base;
    // The TSC counts the host's cycles: a figure of code on the host CPU. A device's row has its
    // own clock beside the host's end-to-end time, never host cycles (nor a host bound).
    const bool tsc = kHasTsc && on_host_.contains(base.backend);
    host.source = tsc ? "host-steady-clock+tsc" : "host-steady-clock";
    fill(host, s.host_ns, s.runs, tsc ? median_of(s.tsc) : 0);
    host.measured_s = s.measured_s;
    emit(host, report);
    if (s.device_ns.empty()) return;
    BenchRow dev = base;
    dev.source = s.device_source;
    fill(dev, s.device_ns, s.runs, s.device_cycles.empty() ? 0 : median_of(s.device_cycles));
    emit(dev, report);
  }

  Backend* backend_for(const BackendRow& row, int threads, BenchReport& report) {
    auto key = std::pair{row.name, threads};
    if (auto it = cache_.find(key); it != cache_.end()) return it->second.get();
    BackendOptions bo = o_.backend_options;
    bo.threads = threads;
    OpenedBackend opened = open_backend(row, bo);
    std::unique_ptr<Backend> b = std::move(opened.backend);
    const std::string& why = opened.why_not;
    if (!why.empty() && threads == 0) report.skipped.push_back(row.name + ": " + why);
    return (cache_[key] = std::move(b)).get();
  }

  static double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  static BenchRow row_for(const std::string& backend, const BenchPoint& pt) {
    BenchRow r;
    r.backend = backend, r.sweep = pt.sweep, r.setting = pt.setting;
    r.width = pt.params.width, r.height = pt.params.height,
    r.search_radius = pt.params.search_radius;
    r.batch = pt.batch,
    r.threads = pt.threads ? pt.threads : static_cast<int>(std::thread::hardware_concurrency());
    r.threads_requested = pt.threads;
    r.params = params_json(pt.params);
    r.pois_per_frame = static_cast<long>(poi_count(pt.params));
    return r;
  }

  static void fill(BenchRow& r, const std::vector<double>& ns, int runs, double cycles) {
    r.repeats = static_cast<int>(ns.size());
    r.processes = 1;
    r.samples_per_process = {r.repeats};
    r.runs_per_sample = runs;
    r.samples_ns_per_frame = ns;
    r.median_ns_per_frame = median_of(ns);
    std::tie(r.median_ci_low_ns, r.median_ci_high_ns) = median_ci95(ns);
    r.min_ns_per_frame = *std::min_element(ns.begin(), ns.end());
    r.max_ns_per_frame = *std::max_element(ns.begin(), ns.end());
    r.noisy = is_noisy(r.median_ns_per_frame, r.median_ci_low_ns, r.median_ci_high_ns,
                       r.min_ns_per_frame);
    r.frames_per_s = 1e9 / r.median_ns_per_frame;
    r.ns_per_poi = r.median_ns_per_frame / static_cast<double>(r.pois_per_frame);
    r.cycles_per_frame = cycles;
    r.process_medians_ns_per_frame = {r.median_ns_per_frame};
  }

  std::string pad(const std::string& name) const { return pad_name(name, name_width_); }

  void note(BenchRow r, const std::string& why, BenchReport& report) {
    r.note = why;
    out_ << pad_name(r.backend, name_width_) << "  " << why << "\n";
    report.rows.push_back(r);
  }

  // What set_row_bound needs to know of the row's backend at this point.
  BoundInputs bound_inputs(const BenchRow& r, BenchReport& report) {
    BoundInputs in;
    in.host = bound_ ? &*bound_ : nullptr;
    in.why_none = o_.measure_bound ? "this host has no SAD ceiling to measure (x86-64 only)"
                                   : "not measured (bench --no-bound)";
    in.host_bytes_per_cycle = [this, &report](int t) { return bound_bytes_per_cycle(t, report); };
    in.tsc_hz = [&report] {
      if (report.tsc_hz <= 0) report.tsc_hz = measure_tsc_hz();
      return report.tsc_hz;
    };
    in.on_host = on_host_.contains(r.backend);
    in.device_kind = device_kind_;
    in.device = device_bound_;
    return in;
  }

  // The row's bound and the fraction of it achieved (bench_bound.hpp), and the speed-up over
  // ref-original's row of the same point and clock, which registry order has emitted already.
  void derive(BenchRow& r, BenchReport& report) {
    set_row_bound(r, bound_inputs(r, report));
    if (r.bound_fraction > 1)  // no code does the SAD work faster than its bound
      add_note(r,
               "beats its bound: a measuring error (was the machine busy while the bound was "
               "measured?) or a wrong bound");
    if (r.bound.rfind("none: ", 0) == 0) add_note(r, "no bound: " + r.bound.substr(6));
    for (const auto& ref : report.rows)
      if (ref.backend == kReferenceBackend && ref.source == r.source && ref.sweep == r.sweep &&
          ref.setting == r.setting && ref.width == r.width && ref.height == r.height &&
          ref.search_radius == r.search_radius && ref.batch == r.batch &&
          ref.threads == r.threads && ref.median_ns_per_frame > 0)
        r.speedup_vs_reference = ref.median_ns_per_frame / r.median_ns_per_frame;
    if (r.backend == kReferenceBackend) r.speedup_vs_reference = 1.0;
  }

  static void add_note(BenchRow& r, const std::string& what) {
    r.note += (r.note.empty() ? "" : "; ") + what;
  }

  void emit(BenchRow r, BenchReport& report) {
    derive(r, report);
    if (!r.timed_build.empty()) add_note(r, "timed: " + r.timed_build);
    if (r.noisy) add_note(r, kNoisyNote);
    out_ << bench_row_line(r, name_width_) << "\n" << std::flush;
    report.rows.push_back(r);
  }

  const BenchOptions& o_;
  std::ostream& out_;
  std::map<std::pair<std::string, int>, std::unique_ptr<Backend>> cache_;
  std::map<std::string, double> sim_pairs_per_s_;  // exact-clock backends: host simulation speed
  std::map<std::string, std::string> described_;   // each backend's description_line()
  std::set<std::string> on_host_;                  // the backends whose code runs on the host CPU
  std::size_t name_width_;
  std::optional<BenchBound> bound_;
  // The backend being measured: its own bound at the point, and its device's kind.
  std::optional<Backend::DeviceBound> device_bound_;
  std::string device_kind_;
};

// How far each row is from the bound a family offers (the cpu family: the SAD work at the
// fastest SAD instruction's rate, in TSC cycles): the first family with a bound this machine can
// measure gives it. Its one-thread rate is measured before the points, so that the header states
// it; other thread counts when a row first needs them.
std::optional<BenchBound> measure_bound(BenchReport& r) {
  for (const BackendFamily& f : backend_families()) {
    if (!f.measure_bench_bound) continue;
    std::optional<BenchBound> bound = f.measure_bench_bound();
    if (!bound) continue;
    r.bound_name = bound->name;
    r.bound_clock = bound->clock;
    r.bound_bytes_per_cycle = bound->bytes_per_cycle(1);
    r.bound_by_threads.push_back({1, r.bound_bytes_per_cycle});
    return bound;
  }
  return std::nullopt;
}

// The rows to run: all, or the named ones, in registry order either way (one order everywhere).
std::vector<const BackendRow*> rows_to_run(const std::vector<std::string>& names) {
  for (const auto& n : names) (void)find_backend(n);  // an unknown name is an InputError
  std::vector<const BackendRow*> rows;
  for (const auto& r : backend_rows())
    if (names.empty() || std::find(names.begin(), names.end(), r.name) != names.end())
      rows.push_back(&r);
  return rows;
}

std::string points_done(const BenchReport& r) {
  return std::to_string(r.points_done) + " of " + std::to_string(r.points_total) + " bench points";
}

}  // namespace

std::string bench_header_line(std::size_t name_width) {
  std::string line = pad_name("backend", name_width);
  for (const Column& c : kColumns) {
    const std::string name = c.name;
    line += "  " + (c.width == 22 ? name + std::string(c.width - name.size(), ' ')
                                  : std::string(c.width - name.size(), ' ') + name);
  }
  return line + "  note";
}

std::string bench_row_line(const BenchRow& r, std::size_t name_width) {
  if (r.samples_ns_per_frame.empty()) return pad_name(r.backend, name_width) + "  " + r.note;
  // A clock that counts instructions (QEMU's -icount) has no time of its own: its virtual
  // nanoseconds and the rates made of them (kept in the JSON) are no speed of anything.
  const bool instructions = r.cycles_per_frame == 0 && r.instructions_per_frame > 0;
  auto timing = [&](std::string cell) { return instructions ? std::string("-") : cell; };
  const std::string cells[] = {
      r.source, timing(formatted("%.0f", r.median_ns_per_frame)),
      timing(formatted("%.0f", r.median_ci_low_ns) + ".." + formatted("%.0f", r.median_ci_high_ns)),
      timing(formatted("%.1f", r.frames_per_s)), timing(formatted("%.1f", r.ns_per_poi)),
      // A clock that counts instructions (QEMU's -icount) says so in its cell, never "cycles".
      r.cycles_per_frame > 0         ? formatted("%.0f", r.cycles_per_frame)
      : r.instructions_per_frame > 0 ? formatted("%.0f instr", r.instructions_per_frame)
                                     : "-",
      r.bound_per_frame > 0 ? bound_text(r.bound_per_frame, r.bound_unit) : "-",
      r.bound_fraction > 0 ? formatted("%.1f %%", 100 * r.bound_fraction)
      : r.bound.empty()    ? "-"
                           : "none",
      r.speedup_vs_reference > 0 ? formatted("%.2fx", r.speedup_vs_reference) : "-"};
  std::string line = pad_name(r.backend, name_width);
  for (std::size_t i = 0; i < std::size(kColumns); ++i) {
    const auto w = static_cast<std::size_t>(kColumns[i].width);
    const std::string gap(cells[i].size() < w ? w - cells[i].size() : 0, ' ');
    line += "  " + (i == 0 ? cells[i] + gap : gap + cells[i]);
  }
  if (!r.note.empty()) line += "  " + r.note;
  return line;
}

BenchReport run_bench(const BenchOptions& o, std::ostream& out) {
  BenchReport report;
  if (o.planted_slowdown_percent > 0)
    out << "planted slowdown: every sample runs " << o.planted_slowdown_percent
        << " % more batches than it counts (PXFLOW_BENCH_PLANTED_SLOWDOWN)\n";
  const MachineState before = read_machine_state();
  const CpuTimes t0 = read_cpu_times();
  const std::vector<const BackendRow*> rows = rows_to_run(o.backends);
  check_device_option(rows, o.backend_options.device);
  std::size_t name_width = 7;
  for (const BackendRow* row : rows) name_width = std::max(name_width, row->name.size());
  std::optional<BenchBound> bound =
      o.measure_bound ? measure_bound(report) : std::optional<BenchBound>{};
  Bench bench(o, out, name_width, bound);
  out << "backends (what runs, on which device):\n";
  bench.open_all(rows, report);
  if (bound)
    out << "bound: " << bound->name << ", " << formatted("%.1f", report.bound_bytes_per_cycle)
        << " bytes per " << bound->clock
        << " cycle on one thread (measured again on as many threads as a row is given); every "
           "row's bound/frame and the fraction of it achieved: docs/harness.md, \"The bound of "
           "every row\"\n";
  bench.print_header();
  report.points_total = o.points.size();
  try {
    for (const auto& pt : o.points) {
      stop_if_interrupted(points_done(report));
      progress("bench: point " + std::to_string(report.points_done + 1) + " of " +
               std::to_string(o.points.size()) + ": " + point_label(pt));
      validate(pt.params);
      out << "-- " << point_label(pt) << "\n";
      const Inputs in = make_inputs(pt.params, pt.batch);
      std::vector<PoiRecord> expected(poi_count(pt.params) * static_cast<std::size_t>(pt.batch));
      OpCounts counts;
      find_backend(kReferenceBackend).create({})->run(in.batch_for(0), pt.params, expected, counts);
      for (const BackendRow* row : rows) bench.measure(*row, pt, in, expected, report);
      ++report.points_done;
    }
  } catch (const Interrupted& e) {  // the rows measured so far stay: each one is whole
    report.complete = false;
    report.stop =
        Interrupted(e.signal, std::string(signal_name(e.signal)) + " after " + points_done(report));
  }
  progress("");
  for (const auto& s : report.skipped) out << "skipped " << s << "\n";
  report.machine = machine_load(before, t0, read_machine_state(), read_cpu_times());
  out << machine_line(report.machine) << "\n";
  return report;
}

}  // namespace pxflow
