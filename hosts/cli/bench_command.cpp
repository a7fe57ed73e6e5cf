// pxflow bench: throughput sweeps over the backends that pass their check.
#include <fstream>
#include <iostream>

#include "bench.hpp"
#include "command_line.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "frame_io.hpp"
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
  if (a.batches.empty() && a.threads.empty() && a.sizes.empty() && a.radii.empty())
    return default_bench_points(base, a.problem.profile);
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
  o.min_seconds = a.min_time;
  o.backend_options = a.backend_options;
  // `--json -`: the JSON is standard output, so the table goes to standard error.
  const bool json_to_stdout = a.json_path == "-";
  OutputPlan plan;
  OutputFile* const json_file = a.json_path.empty() ? nullptr : &plan.file("--json", a.json_path);
  plan.prepare();
  std::ostream& out = json_to_stdout ? std::cerr : std::cout;
  out << "pxflow bench: " << o.points.size() << " points; each backend's records are checked "
      << "against ref-original before it is timed; ns/frame is the median over repeats "
         "(min..max)\n";
  BenchReport r = run_bench(o, out);
  r.command = a.command;
  const std::string json = bench_json(r).dump(2) + "\n";
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
  sub->add_option("--min-time", a->min_time, "Seconds of repeats per point and backend")
      ->check(CLI::Range(0.0, 600.0))
      ->capture_default_str();
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
