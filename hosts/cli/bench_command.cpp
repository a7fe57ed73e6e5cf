// pxflow bench: throughput sweeps over the backends that pass their check.
#include <fstream>
#include <iostream>

#include "bench.hpp"
#include "command_line.hpp"
#include "commands.hpp"
#include "counted.hpp"
#include "errors.hpp"
#include "frame_io.hpp"
#include "interrupt.hpp"
#include "json_document.hpp"
#include "list_option.hpp"
#include "output_plan.hpp"
#include "progress.hpp"

namespace pxflow::cli {
namespace {

struct BenchArgs {
  ProblemOptions problem;
  std::string backend, backends, batches, thread_sweep, sizes, radii, json_path;
  std::string command;  // the command line as run (command_line.hpp)
  double min_time = 0.25;
  int max_samples = 0;
  bool quick = false;
  // --threads: the host threads of every point but the thread sweep's (0 = all cores).
  CLI::Option *min_time_opt = nullptr, *threads_opt = nullptr;
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
  if (!a.thread_sweep.empty() && a.threads_opt->count() > 0)
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

int run_bench_command(const BenchArgs& a) {
  if (!a.backend.empty() && !a.backends.empty())
    throw InputError("--backend " + a.backend + ": given with --backends " + a.backends +
                     ": give one of them (see pxflow bench --help)");
  BenchOptions o;
  o.backends = split_list(a.backend.empty() ? a.backends : a.backend);
  for (const std::string& name : o.backends) (void)find_backend(name);  // before any output
  o.points = bench_points(a);
  o.min_seconds = a.quick && a.min_time_opt->count() == 0 ? kQuickMinSeconds : a.min_time;
  o.max_samples = a.max_samples;
  o.backend_options = a.backend_options;
  o.backend_options.threads = 0;  // each point's own threads (bench_points)
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
  BenchReport r = run_bench(o, out);
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
  return bench_verdict(r, out);
}

}  // namespace

// What --help and the man page show under Examples (the command line after "pxflow ").
const std::vector<std::string> kBenchExamples = {
    "bench --batch 1,256,4096  # throughput, each backend checked before it is timed",
    "bench --backends cpu,opencl --json bench.json",
};

Command add_bench_command(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  CLI::App* sub = app.add_subcommand(
      "bench", "Time the backends over batch, frame-size, radius and thread sweeps");
  a->problem.add_to(*sub);
  add_backends_option(*sub, a->backends);
  add_backend_option(*sub, a->backend);
  sub->add_option("--batch", a->batches, "Batch sizes, N[,N...] (frame pairs per run)")
      ->check(non_empty_list());
  a->threads_opt =
      add_threads_option(*sub, a->backend_options.threads,
                         "of every point but the thread sweep's (what report --threads N runs)");
  sub->add_option("--thread-sweep", a->thread_sweep,
                  "Thread counts to sweep, N[,N...] (0 = all cores), instead of --threads")
      ->check(non_empty_list());
  sub->add_option("--sizes", a->sizes, "Frame sizes, WxH[,WxH...]")->check(non_empty_list());
  sub->add_option("--radius", a->radii, "Search radii, S[,S...]")->check(non_empty_list());
  a->min_time_opt =
      sub->add_option("--min-time", a->min_time,
                      "Seconds of measured samples per point and backend, at least (5 samples "
                      "at least, however long)")
          ->check(CLI::Range(0.0, 600.0))
          ->capture_default_str();
  sub->add_option("--max-samples", a->max_samples,
                  "Stop a point after N samples even before --min-time (0 = no cap)")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  sub->add_flag("--quick", a->quick,
                "The default sweeps' quick subset: batch <= 256 and the frame sizes, no radius or "
                "thread sweep, --min-time 0.05 unless given (what report --quick runs)");
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
