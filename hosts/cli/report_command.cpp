// pxflow report: runs (or reads) check and bench results and writes the report files.
#include <fstream>
#include <iostream>

#include "bench.hpp"
#include "check.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "list_option.hpp"
#include "report.hpp"

namespace pxflow::cli {
namespace {

struct ReportArgs {
  std::string out_dir, check_json, bench_json, backends;
  std::uint64_t seed = 1;
  bool quick = false;
};

Json read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open");
  try {
    return Json::parse(in);
  } catch (const std::exception&) {
    throw InputError(path + ": not valid JSON (expected the output of pxflow check/bench --json)");
  }
}

int run_report(const ReportArgs& a) {
  ReportInputs in;
  const std::string backends = a.backends.empty() ? "" : " --backends " + a.backends;
  in.report_command = "pxflow report --out " + a.out_dir + backends + (a.quick ? " --quick" : "");
  if (!a.check_json.empty()) {
    in.check = read_json(a.check_json);
    in.check_command = "pxflow check --json " + a.check_json + " (as recorded in that file)";
  } else {
    CheckOptions o;
    o.backends = split_list(a.backends);
    o.corpus.seed = a.seed;
    in.check_command = "pxflow check --seed " + std::to_string(a.seed) + backends;
    std::cout << "== " << in.check_command << "\n";
    const CheckReport r = run_check(o, std::cout);
    std::cout << r.passed << " passed, " << r.failed << " failed, " << r.skipped << " skipped\n";
    in.check = check_json(r);
  }
  if (!a.bench_json.empty()) {
    in.bench = read_json(a.bench_json);
    in.bench_command = "pxflow bench --json " + a.bench_json + " (as recorded in that file)";
  } else {
    BenchOptions o;
    o.backends = split_list(a.backends);
    o.points = default_bench_points(profile("px4flow-64"), "px4flow-64");
    if (a.quick) {
      std::erase_if(o.points, [](const BenchPoint& p) { return p.batch > 256 || p.sweep == "radius" || p.sweep == "threads"; });
      o.min_seconds = 0.05;
    }
    in.bench_command = "pxflow bench" + backends + (a.quick ? " (quick subset: batch <= 256, no radius/thread sweep)" : "");
    std::cout << "== " << in.bench_command << "\n";
    in.bench = bench_json(run_bench(o, std::cout));
  }
  write_report(a.out_dir, in);
  std::cout << "wrote " << a.out_dir << "/report.md, report.html, results.json, results.csv\n";
  return in.check.value("failed", 0) == 0 ? 0 : 1;
}

}  // namespace

Command add_report_command(CLI::App& app) {
  auto a = std::make_shared<ReportArgs>();
  CLI::App* sub = app.add_subcommand("report", "Write report.md, report.html, results.json and results.csv");
  sub->add_option("--out", a->out_dir, "Folder to write the report into")->required();
  sub->add_option("--check-json", a->check_json, "Use this `pxflow check --json` file instead of running the check");
  sub->add_option("--bench-json", a->bench_json, "Use this `pxflow bench --json` file instead of running the bench");
  sub->add_option("--backends", a->backends, "Comma-separated backends (default: all)");
  sub->add_option("--seed", a->seed, "Seed of the check's random pairs")->capture_default_str();
  sub->add_flag("--quick", a->quick, "A shorter bench (batch <= 256, no radius or thread sweeps)");
  return {sub, [a] { return run_report(*a); }};
}

}  // namespace pxflow::cli
