// pxflow bench: throughput sweeps over the backends that pass their check.
#include <fstream>
#include <iostream>

#include "bench.hpp"
#include "command_line.hpp"
#include "commands.hpp"
#include "counted.hpp"
#include "errors.hpp"
#include "frame_io.hpp"
#include "json_document.hpp"
#include "list_option.hpp"
#include "output_plan.hpp"
#include "progress.hpp"

namespace pxflow::cli {
namespace {

struct BenchArgs {
  ProblemOptions problem;
  std::string backend, backends, batches, threads, sizes, radii, json_path;
  std::string command;  // the command line as run (command_line.hpp)
  double min_time = 0.25;
  bool quick = false;
  int sweep_threads = 0;  // the default sweeps' host threads (0 = all cores)
  CLI::Option *min_time_opt = nullptr, *sweep_threads_opt = nullptr;
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
    throw InputError("--size and --set width/height both set the frame size; give one");
  const Params base = a.problem.resolve(std::nullopt);
  const bool custom =
      !a.batches.empty() || !a.threads.empty() || !a.sizes.empty() || !a.radii.empty();
  if (custom && (a.quick || a.sweep_threads_opt->count() > 0))
    throw InputError(std::string(a.quick ? "--quick" : "--sweep-threads") +
                     ": shapes the default sweeps; --batch, --threads, --size and --radius "
                     "replace them: give one kind (see pxflow bench --help)");
  if (!custom) {
    std::vector<BenchPoint> pts = a.quick ? quick_bench_points(base, a.problem.profile)
                                          : default_bench_points(base, a.problem.profile);
    set_sweep_threads(pts, a.sweep_threads);
    return pts;
  }
  const auto batches =
      a.batches.empty() ? std::vector<int>{256} : int_list(a.batches, "--batch", 1, 1 << 20);
  const auto threads =
      a.threads.empty() ? std::vector<int>{0} : int_list(a.threads, "--threads", 0, 1024);
  const auto radii =
      a.radii.empty() ? std::vector<int>{base.search_radius} : int_list(a.radii, "--radius", 1, 31);
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

int run_bench_command(const BenchArgs& a) {
  if (!a.backend.empty() && !a.backends.empty())
    throw InputError("--backend " + a.backend + ": given with --backends " + a.backends +
                     ": give one of them (see pxflow bench --help)");
  BenchOptions o;
  o.backends = split_list(a.backend.empty() ? a.backends : a.backend);
  for (const std::string& name : o.backends) (void)find_backend(name);  // before any output
  o.points = bench_points(a);
  o.min_seconds = a.quick && a.min_time_opt->count() == 0 ? kQuickMinSeconds : a.min_time;
  o.backend_options = a.backend_options;
  // `--json -`: the JSON is standard output, so the table goes to standard error.
  const bool json_to_stdout = a.json_path == "-";
  OutputPlan plan;
  OutputFile* const json_file = a.json_path.empty() ? nullptr : &plan.file("--json", a.json_path);
  plan.prepare();
  std::ostream& out = json_to_stdout ? std::cerr : std::cout;
  out << "pxflow bench: " << counted(o.points.size(), "point")
      << "; each backend's records are checked "
      << "against ref-original before it is timed; ns/frame is the median over repeats "
         "(min..max)\n";
  BenchReport r = run_bench(o, out);
  r.command = a.command;
  const std::string json = json_document(bench_json(r));
  if (json_file) json_file->write(json);
  return 0;
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
  sub->add_option("--backends", a->backends,
                  "Comma-separated backends (default: all that can run)");
  sub->add_option("--backend", a->backend, "One backend (see `pxflow backends`)");
  sub->add_option("--batch", a->batches, "Batch sizes, N[,N...] (frame pairs per run)")
      ->check(non_empty_list());
  sub->add_option("--threads", a->threads, "Thread counts, N[,N...] (0 = all cores)")
      ->check(non_empty_list());
  sub->add_option("--size", a->sizes, "Frame sizes, WxH[,WxH...]")->check(non_empty_list());
  sub->add_option("--radius", a->radii, "Search radii, S[,S...]")->check(non_empty_list());
  a->min_time_opt =
      sub->add_option("--min-time", a->min_time, "Seconds of repeats per point and backend")
          ->check(CLI::Range(0.0, 600.0))
          ->capture_default_str();
  sub->add_flag("--quick", a->quick,
                "The default sweeps' quick subset: batch <= 256 and the frame sizes, no radius or "
                "thread sweep, --min-time 0.05 unless given (what report --quick runs)");
  a->sweep_threads_opt =
      sub->add_option("--sweep-threads", a->sweep_threads,
                      "Host threads of every default-sweep point but the thread sweep's "
                      "(0 = all cores; what report --threads N runs)")
          ->check(CLI::Range(0, 1024));
  sub->add_option("--device", a->backend_options.device,
                  "Device index or name substring (GPU backends)");
  sub->add_option("--json", a->json_path,
                  "Write the rows as JSON to FILE ('-': standard output, the table to stderr)");
  add_progress_flag(*sub);
  return {sub,
          [a, sub] {
            a->command = given_command_line(*sub);
            return run_bench_command(*a);
          },
          kBenchExamples};
}

}  // namespace pxflow::cli
