// pxflow bench: throughput sweeps over the backends that pass their check.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "bench.hpp"
#include "bench_processes.hpp"
#include "command_line.hpp"
#include "commands.hpp"
#include "counted.hpp"
#include "errors.hpp"
#include "frame_io.hpp"
#include "interrupt.hpp"
#include "json_document.hpp"
#include "list_option.hpp"
#include "machine_state.hpp"
#include "output_plan.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "registry.hpp"

namespace pxflow::cli {
namespace {

struct BenchArgs {
  ProblemOptions problem;
  std::string backend, backends, batches, thread_sweep, sizes, radii, json_path;
  std::string command;  // the command line as run (command_line.hpp)
  double min_time = 0.25;
  int max_samples = 0;
  int processes = kDefaultProcesses;
  bool quick = false, no_bound = false;
  // --threads: the host threads of every point but the thread sweep's (0 = all cores).
  const CommandSpec* sub = nullptr;
  BackendOptions backend_options;
};

std::vector<int> int_list(const std::string& text, const char* what, int lo, int hi) {
  std::vector<int> out;
  for (const auto& item : split_list(text)) out.push_back(parse_int(item, what, lo, hi));
  return out;
}

// Explicit sweep flags give the cartesian product of their lists; none gives the default sweeps.
std::vector<BenchPoint> bench_points(const BenchArgs& a) {
  // A sweep flag and a --set of the same parameter would silently overrule one another.
  if (!a.radii.empty() && a.problem.sets_key("search_radius"))
    throw InputError("--radius and --set search_radius both set the search radius; give one");
  if (!a.sizes.empty() && (a.problem.sets_key("width") || a.problem.sets_key("height")))
    throw InputError("--sizes and --set width/height both set the frame size; give one");
  const Params base = a.problem.resolve(std::nullopt);
  const int threads_given = a.backend_options.threads;
  if (!a.thread_sweep.empty() && a.sub->count("--threads") > 0)
    throw InputError("--threads " + std::to_string(threads_given) + ": given with --thread-sweep " +
                     a.thread_sweep + ": give one of them (see pxflow bench --help)");
  const bool custom =
      !a.batches.empty() || !a.thread_sweep.empty() || !a.sizes.empty() || !a.radii.empty();
  if (custom && a.quick)
    throw InputError(
        "--quick: shapes the default sweeps; --batch, --thread-sweep, --sizes and --radius "
        "replace them: give one kind (see pxflow bench --help)");
  if (!custom) {
    std::vector<BenchPoint> pts = a.quick ? quick_bench_points(base, a.problem.profile)
                                          : default_bench_points(base, a.problem.profile);
    set_sweep_threads(pts, threads_given);
    return pts;
  }
  const auto batches =
      a.batches.empty() ? std::vector<int>{256} : int_list(a.batches, "--batch", 1, 1 << 20);
  const auto threads = a.thread_sweep.empty() ? std::vector<int>{threads_given}
                                              : int_list(a.thread_sweep, "--thread-sweep", 0, 1024);
  const auto radii = a.radii.empty()
                         ? std::vector<int>{base.search_radius}
                         : int_list(a.radii, "--radius", kMinSearchRadius, kMaxSearchRadius);
  std::vector<FrameSize> sizes;
  for (const auto& s : split_list(a.sizes)) sizes.push_back(parse_frame_size(s));
  if (sizes.empty()) sizes.push_back({base.width, base.height});
  std::vector<BenchPoint> pts;
  for (auto size : sizes)
    for (int S : radii)
      for (int batch : batches)
        for (int t : threads) {
          Params p = base;
          p.width = size.width, p.height = size.height, p.search_radius = S;
          validate(p);
          pts.push_back({"custom", a.problem.profile, p, batch, t});
        }
  return pts;
}

// Exit 1 when a row's records differ from ref-original or nothing was timed at all: a bench
// that measured nothing is no success.
int bench_verdict(const BenchReport& r, std::ostream& out) {
  int timed = 0, differ = 0;
  for (const BenchRow& row : r.rows) {
    timed += !row.samples_ns_per_frame.empty();
    differ += row.note.find("records differ") != std::string::npos;
  }
  if (differ > 0)
    out << "pxflow bench: " << counted(differ, "row") << " not timed because its records differ "
        << "from ref-original (exit 1; pxflow check names the difference)\n";
  else if (timed == 0)
    out << "pxflow bench: nothing was timed (exit 1)\n";
  return differ > 0 || timed == 0 ? 1 : 0;
}

// The options of every process but the ones each gets its own value of (bench_in_processes).
constexpr const char* kPerProcess[] = {"--processes", "--json",    "--min-time",
                                       "--backends",  "--backend", "--progress"};

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ",") + n;
  return s;
}

// The command line of every process: the global options and bench's as given but those of
// kPerProcess, then one process's share of --min-time (`seconds`) and its JSON on stdout.
std::vector<std::string> process_command(const BenchArgs& a, const char* seconds) {
  std::vector<std::string> argv = {own_executable()};
  for (const auto& [name, value] : given_option_list(*a.sub->parent))
    argv.push_back(name), value ? argv.push_back(*value) : void();
  argv.push_back("bench");
  for (const auto& [name, value] : given_option_list(*a.sub)) {
    if (std::ranges::find(kPerProcess, name) != std::end(kPerProcess)) continue;
    argv.push_back(name);
    if (value) argv.push_back(*value);
  }
  argv.insert(argv.end(), {"--processes", "1", "--min-time", seconds, "--json", "-"});
  return argv;
}

// The backends of the rows that vary from process to process (timed, by a clock that is not
// exact): the ones the processes after the first measure again.
std::vector<std::string> varying_backends(const BenchReport& first) {
  std::vector<std::string> backends;
  for (const BenchRow& r : first.rows)
    if (!r.samples_ns_per_frame.empty() && !r.exact_clock &&
        std::ranges::find(backends, r.backend) == backends.end())
      backends.push_back(r.backend);
  return backends;
}

// What the processes gave: their reports in order, and what stopped them early, if anything.
struct ProcessRuns {
  std::vector<BenchReport> runs;
  std::optional<Interrupted> stop;
  std::string failed;
};

// Runs the processes of `argv`: the first over `backends`, the others over its varying rows.
ProcessRuns run_processes(const BenchArgs& a, std::vector<std::string> argv,
                          std::vector<std::string> backends, std::ostream& out) {
  ProcessRuns done;
  for (int k = 1; k <= a.processes; ++k) {
    std::vector<std::string> args = argv;
    if (!backends.empty()) args.insert(args.end(), {"--backends", joined(backends)});
    progress("bench: process " + std::to_string(k) + " of " + std::to_string(a.processes));
    BenchProcess p;
    try {
      p = run_bench_process(args);
    } catch (const Interrupted& e) {
      done.stop = Interrupted(e.signal, std::string(signal_name(e.signal)) + " after " +
                                            counted(done.runs.size(), "process") + " of " +
                                            std::to_string(a.processes));
      break;
    }
    if (p.status == 2 && done.runs.empty()) throw InputError(p.last_error_line);
    if (p.bench.is_null() || (p.status != 0 && p.status != 1)) {
      done.failed = "bench process " + std::to_string(k) + " of " + std::to_string(a.processes) +
                    " failed (" + p.last_error_line + ")";
      break;
    }
    done.runs.push_back(bench_report_from_json(p.bench));
    out << "process " << k << " of " << a.processes << ": " << done.runs.back().rows.size()
        << " rows\n";
    if (k > 1) continue;
    if (!a.no_bound) argv.push_back("--no-bound");  // the first process measured it
    backends = varying_backends(done.runs.front());
    if (backends.empty()) break;
  }
  progress("");
  return done;
}

// The processes' reports as one, incomplete when a process was stopped or failed.
BenchReport combined_report(const ProcessRuns& done, const BenchOptions& o) {
  BenchReport r;
  if (!done.runs.empty()) r = combine_processes(done.runs);
  r.points_total = o.points.size();
  if (done.runs.empty()) r.complete = false, r.points_done = 0;
  if (done.stop || !done.failed.empty()) r.complete = false;
  if (done.stop) r.stop = *done.stop;
  if (!done.failed.empty()) r.failed = done.failed;
  return r;
}

void print_combined_report(const BenchReport& r, std::ostream& out) {
  out << "backends (what runs, on which device):\n";
  for (const Json& d : r.backends) {
    const std::string line = description_line(d);
    out << "  " << d.value("backend", "") << "  "
        << (line.empty() ? "as named, on the host CPU" : line) << "\n";
  }
  print_bench_rows(r, out);
  for (const auto& s : r.skipped) out << "skipped " << s << "\n";
  out << machine_line(r.machine) << "\n";
}

// `bench --processes R`: this binary's bench R times, each a process of its own with 1/R of
// --min-time; rows of an exact clock (a deterministic count) and rows not timed are taken from the
// first process alone. A signal, or a process that fails, keeps the processes finished so far.
BenchReport bench_in_processes(const BenchArgs& a, const BenchOptions& o, std::ostream& out) {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.6g", o.min_seconds / a.processes);
  std::vector<std::string> argv = process_command(a, seconds);
  out << "each point in " << a.processes << " processes of " << seconds
      << " s of samples per backend; a row's median and 95% interval are its processes' "
         "medians'\n";
  BenchReport r = combined_report(run_processes(a, std::move(argv), o.backends, out), o);
  print_combined_report(r, out);
  return r;
}

int run_bench_command(const BenchArgs& a) {
  if (!a.backend.empty() && !a.backends.empty())
    throw InputError("--backend " + a.backend + ": given with --backends " + a.backends +
                     ": give one of them (see pxflow bench --help)");
  BenchOptions o;
  o.backends = split_list(a.backend.empty() ? a.backends : a.backend);
  for (const std::string& name : o.backends) (void)find_backend(name);  // before any output
  o.points = bench_points(a);
  o.min_seconds = a.quick && a.sub->count("--min-time") == 0 ? kQuickMinSeconds : a.min_time;
  o.max_samples = a.max_samples;
  o.backend_options = a.backend_options;
  o.backend_options.threads = 0;  // each point's own threads (bench_points)
  o.planted_slowdown_percent = planted_slowdown_from_environment();
  o.measure_bound = !a.no_bound;
  // `--json -`: the JSON is standard output, so the table goes to standard error.
  const bool json_to_stdout = a.json_path == "-";
  OutputPlan plan;
  OutputFile* const json_file = a.json_path.empty() ? nullptr : &plan.file("--json", a.json_path);
  plan.prepare();
  std::ostream& out = json_to_stdout ? std::cerr : std::cout;
  out << "pxflow bench: " << counted(o.points.size(), "point")
      << "; each backend's records are checked "
      << "against ref-original before it is timed, then timed for at least --min-time seconds "
         "of samples; ns/frame is the median sample, with its 95% confidence interval\n";
  BenchReport r = a.processes > 1 ? bench_in_processes(a, o, out) : run_bench(o, out);
  r.command = a.command;
  const std::string json = json_document(bench_json(r));
  if (json_file) json_file->write(json);
  if (r.stop) {  // app.cpp prints the line, exit 128 + the signal
    const std::string where =
        !json_file       ? "nothing written (--json FILE keeps a stopped bench's rows)"
        : json_to_stdout ? "the JSON on standard output holds its rows, \"complete\": false"
                         : a.json_path + " holds its rows, \"complete\": false";
    throw Interrupted(r.stop->signal, std::string(r.stop->what()) + "; " + where);
  }
  if (!r.failed.empty()) {
    out << "pxflow bench: " << r.failed << "; "
        << (json_file ? a.json_path + " holds the processes before it, \"complete\": false"
                      : std::string("nothing written"))
        << " (exit 1)\n";
    return 1;
  }
  return bench_verdict(r, out);
}

}  // namespace

const std::vector<std::string> kBenchExamples = {
    "bench --batch 1,256,4096  # throughput, each backend checked before it is timed",
    "bench --backends cpu,opencl --json bench.json",
};

Command add_bench_command(CommandSpec& app) {
  auto a = std::make_shared<BenchArgs>();
  CommandSpec* sub = &app.add_subcommand(
      "bench", "Time the backends over batch, frame-size, radius and thread sweeps");
  a->sub = sub;
  a->problem.add_to(*sub);
  add_backends_option(*sub, a->backends);
  add_backend_option(*sub, a->backend);
  sub->add("--batch", &a->batches, "Batch sizes, N[,N...] (frame pairs per run)")
      .checked(non_empty_list());
  add_threads_option(*sub, a->backend_options.threads,
                     "of every point but the thread sweep's (what report --threads N runs)");
  sub->add("--thread-sweep", &a->thread_sweep,
           "Thread counts to sweep, N[,N...] (0 = all cores), instead of --threads")
      .checked(non_empty_list());
  sub->add("--sizes", &a->sizes, "Frame sizes, WxH[,WxH...]").checked(non_empty_list());
  sub->add("--radius", &a->radii, "Search radii, S[,S...]").checked(non_empty_list());
  sub->add("--min-time", &a->min_time,
           "Seconds of measured samples per point and backend, at least, split over "
           "the processes (5 samples in each at least, however long)")
      .with_default()
      .real_in(0, 600);
  sub->add("--processes", &a->processes,
           "Measure each point in R processes of this binary, each after its own warm-up: "
           "a row's median and interval are over the processes' medians, so that "
           "run-to-run variance is in them (1: one process, the samples' statistics; "
           "pxflow compare then calls a change inconclusive)")
      .type("R")
      .in_range(1, 100)
      .with_default();
  sub->add("--max-samples", &a->max_samples,
           "Stop a point after N samples even before --min-time (0 = no cap)")
      .in_range(0, 1000000)
      .with_default();
  sub->flag("--quick", a->quick,
            "The default sweeps' quick subset: batch <= 256 and the frame sizes, no radius or "
            "thread sweep, --min-time 0.05 unless given (what report --quick runs)");
  sub->flag("--no-bound", a->no_bound,
            "Do not measure the host's SAD ceiling (about half a second per process; the rows "
            "of the host CPU, OpenCL and Vulkan then say no bound): for gates that compare "
            "builds, not kernels with their bound");
  add_device_option(*sub, a->backend_options.device);
  add_json_option(*sub, a->json_path,
                  "the table then goes to stderr; a bench a signal stops writes the rows it "
                  "measured, \"complete\": false");
  add_progress_flag(*sub);
  // Spellings that meant something else here than in the other commands.
  add_renamed_option(*sub, "--size", "--sizes WxH[,WxH...]");
  add_renamed_option(*sub, "--sweep-threads", "--threads N");
  return {sub,
          [a, sub] {
            a->command = given_command_line(*sub);
            return run_bench_command(*a);
          },
          kBenchExamples,
          {"--backend ref-local --batch 1 --sizes 64x64 --min-time 0"},
          {"--backend ref-local --batch 1,16 --sizes 64x64,320x240 --min-time 2 --json "
           "{KEPT}.json"}};
}

}  // namespace pxflow::cli
