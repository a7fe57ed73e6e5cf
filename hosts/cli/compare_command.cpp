// pxflow compare: bench files of other machines, builds or drivers, row by row against the first
// (docs/harness.md, "Comparing bench files"); a CI regression gate with --fail-above.
#include <filesystem>
#include <iostream>
#include <sstream>

#include "bench_compare.hpp"
#include "bench_processes.hpp"
#include "command_line.hpp"
#include "commands.hpp"
#include "counted.hpp"
#include "errors.hpp"
#include "input_file.hpp"
#include "json_document.hpp"
#include "output_plan.hpp"
#include "owned_folder.hpp"
#include "path_options.hpp"
#include "progress.hpp"
#include "real_options.hpp"

namespace pxflow::cli {
namespace {

struct CompareArgs {
  std::vector<std::string> files;
  std::string out_dir;
  double fail_above = -1;  // -1: not a gate
  bool across_machines = false;
  std::vector<std::string> run;  // --run OLD NEW: two pxflow binaries
  int rounds = kDefaultRounds;
  std::string bench_args;
  const CommandSpec* sub = nullptr;
  static constexpr int kDefaultRounds = 10;
};

// Each file read and checked before anything is written: a wrong one is one line, exit 2.
std::vector<BenchFile> read_bench_files(const std::vector<std::string>& paths) {
  if (paths.size() < 2)
    throw InputError(
        "compare needs two bench files or more, the first the baseline, or --run OLD NEW (see "
        "pxflow compare --help)");
  std::vector<BenchFile> files;
  for (const std::string& path : paths) {
    BenchFile f{path, file_label(files.size()), {}};
    const std::string text = read_input_text(path, path);
    try {
      f.bench = Json::parse(text);
    } catch (const std::exception&) {
      throw InputError(path + ": not valid JSON (expected the output of pxflow bench --json)");
    }
    check_bench_file(path, f.bench);
    files.push_back(std::move(f));
  }
  return files;
}

// --bench-args split into words; the options each process gets from compare refused.
std::vector<std::string> bench_words(const std::string& text) {
  std::vector<std::string> words;
  std::istringstream in(text);
  for (std::string w; in >> w;) {
    if (w.find_first_of("'\"\\") != std::string::npos)
      throw InputError("--bench-args: '" + w +
                       "': no quoting here (words are split at spaces); give global options such "
                       "as --dut before the command: pxflow --dut ... compare --run ...");
    for (const char* own : {"--processes", "--json", "--progress"})
      if (w == own || w.rfind(std::string(own) + "=", 0) == 0)
        throw InputError("--bench-args: " + w + ": compare --run gives each bench process " + own +
                         " itself; leave it out");
    words.push_back(w);
  }
  return words;
}

// compare --run OLD NEW: the two binaries' benches alternately, A B B A A B ..., each a process of
// its own (`bench ... --processes 1 --json -`), so that a drift of the machine meets both alike;
// each side's processes are then one bench file (bench_processes.hpp).
std::vector<BenchFile> run_two_builds(const CompareArgs& a) {
  const std::vector<std::string> words = bench_words(a.bench_args);
  std::vector<std::string> globals;
  for (const auto& [name, value] : given_option_list(*a.sub->parent))
    globals.push_back(name), value ? globals.push_back(*value) : void();
  std::vector<BenchReport> runs[2];
  Json built[2];  // each binary's "pxflow" (version, commit), from its first process
  for (int round = 1; round <= a.rounds; ++round)
    for (int turn = 0; turn < 2; ++turn) {
      const int side = round % 2 == 1 ? turn : 1 - turn;
      const std::string label = file_label(static_cast<std::size_t>(side));
      std::vector<std::string> argv = {a.run[static_cast<std::size_t>(side)]};
      argv.insert(argv.end(), globals.begin(), globals.end());
      argv.push_back("bench");
      argv.insert(argv.end(), words.begin(), words.end());
      argv.insert(argv.end(), {"--processes", "1", "--json", "-"});
      progress("compare --run: round " + std::to_string(round) + " of " + std::to_string(a.rounds) +
               ": " + label);
      BenchProcess p;
      try {
        p = run_bench_process(argv);
      } catch (const SpawnError& e) {
        throw InputError(label + ": " + e.what());
      }
      const std::string who = label + " (" + argv[0] + " bench)";
      if (p.status == 2) throw InputError(who + ": " + p.last_error_line);
      if (p.bench.is_null() || (p.status != 0 && p.status != 1))
        throw OutputError(who + " failed in round " + std::to_string(round) + ": " +
                          p.last_error_line);
      try {
        check_bench_file(who, p.bench);
        runs[side].push_back(bench_report_from_json(p.bench));
        if (built[side].is_null() && p.bench.contains("pxflow")) built[side] = p.bench["pxflow"];
      } catch (const std::exception& e) {
        throw InputError(who + ": its --json is not a bench file of this pxflow (" + e.what() +
                         ")");
      }
    }
  progress("");
  std::vector<BenchFile> files;
  for (int side = 0; side < 2; ++side) {
    BenchReport r = combine_processes(runs[side]);
    r.command = a.run[static_cast<std::size_t>(side)] + " bench " + a.bench_args +
                " (compare --run, " + counted(runs[side].size(), "process") + ")";
    Json bench = bench_json(r);
    if (!built[side].is_null()) bench["pxflow"] = built[side];
    files.push_back({a.run[static_cast<std::size_t>(side)],
                     file_label(static_cast<std::size_t>(side)), std::move(bench)});
  }
  std::cout << "compare --run: " << a.rounds << " rounds, A and B alternately (A B, B A, ...), "
            << "each a bench process of its own\n";
  return files;
}

// The list of the files a compare folder holds (io/owned_folder.hpp).
constexpr const char* kCompareManifest = ".pxflow-compare";

int run_compare(const CompareArgs& a) {
  if (!a.run.empty() && !a.files.empty())
    throw InputError(
        "--run OLD NEW: given with bench files; give one of them (see pxflow "
        "compare --help)");
  if (a.run.empty() && (a.sub->count("--rounds") > 0 || !a.bench_args.empty()))
    throw InputError("--rounds and --bench-args go with --run OLD NEW (see pxflow compare --help)");
  OutputPlan plan;
  plan.read_all(a.files);
  OutputFile *json_out = nullptr, *csv_out = nullptr, *listed = nullptr;
  std::vector<OutputFile*> bench_out;
  std::vector<std::string> names = {"compare.json", "compare.csv"};
  if (!a.run.empty()) names.insert(names.end(), {"bench-A.json", "bench-B.json"});
  if (!a.out_dir.empty()) {
    namespace fs = std::filesystem;
    plan.make_folder("--out", a.out_dir, kCompareManifest);
    json_out = &plan.file("--out", (fs::path(a.out_dir) / "compare.json").string());
    csv_out = &plan.file("--out", (fs::path(a.out_dir) / "compare.csv").string());
    listed = &plan.file("--out", (fs::path(a.out_dir) / kCompareManifest).string());
    for (std::size_t i = 2; i < names.size(); ++i)
      bench_out.push_back(&plan.file("--out", (fs::path(a.out_dir) / names[i]).string()));
  }
  const std::vector<BenchFile> files =
      a.run.empty() ? read_bench_files(a.files) : std::vector<BenchFile>{};
  plan.prepare();
  const std::vector<BenchFile> ran = a.run.empty() ? std::vector<BenchFile>{} : run_two_builds(a);
  const std::vector<BenchFile>& compared = a.run.empty() ? files : ran;
  const BenchComparison c = compare_bench_files(compared, {a.across_machines, a.fail_above});
  print_comparison(c, std::cout);
  if (json_out) {
    json_out->write(json_document(comparison_json(c)));
    csv_out->write(comparison_csv(c));
    for (std::size_t i = 0; i < bench_out.size(); ++i)
      bench_out[i]->write(json_document(ran[i].bench));
    listed->write(manifest_text(names));
    std::cout << "wrote " << a.out_dir << "/" << names.front();
    for (std::size_t i = 1; i < names.size(); ++i) std::cout << ", " << names[i];
    std::cout << "\n";
  }
  const int exit = comparison_exit(c);
  int failed = 0, inconclusive = 0;
  for (const CompareRow& r : c.rows)
    failed += r.gate == "fail", inconclusive += r.gate == "inconclusive";
  if (c.rows.empty())
    std::cout << "pxflow compare: no row was compared (exit 1): the files measured no point "
                 "alike (see 'not compared' above)\n";
  else if (a.fail_above >= 0)
    std::cout << "pxflow compare: " << counted(c.rows.size(), "row") << " gated at " << a.fail_above
              << " %: " << failed << " failed, " << inconclusive << " inconclusive, "
              << c.rows.size() - failed - inconclusive << " passed (exit " << exit << ")\n";
  return a.fail_above >= 0 || c.rows.empty() ? exit : 0;
}

}  // namespace

const std::vector<std::string> kCompareExamples = {
    "compare main.json today.json --fail-above 5  # exit 1: slower by more than 5 %; 3: undecided",
    "compare --run main/pxflow pr/pxflow --bench-args \"--backends cpu --batch 256\" --fail-above "
    "5",
    "compare laptop.json h200.json --across-machines --out cmp  # cmp/compare.json and .csv",
};

Command add_compare_command(CommandSpec& app) {
  auto a = std::make_shared<CompareArgs>();
  CommandSpec* sub = &app.add_subcommand(
      "compare",
      "Compare bench files (pxflow bench --json) of other machines, builds or drivers with the "
      "first: per backend and point, the ratio of medians and a Mann-Whitney U test");
  a->sub = sub;
  sub->footer =
      "Rows are compared only when their work is the same: backend, clock, sweep, profile, every "
      "parameter (--set), batch, threads and device; a row that differs in any is listed as not "
      "comparable, with what differs. Files of different machines need --across-machines (then "
      "threads are compared as asked, 'all' with 'all', and devices may differ). Over the two "
      "rows' process medians (bench --processes): ratio = the Hodges-Lehmann estimate of "
      "time / baseline time (> 1: slower) with its distribution-free 95% interval, and the "
      "Mann-Whitney U test (p < 0.05: significant); an exact clock (a deterministic model) "
      "compares its counts. --fail-above PCT fails a row only when its whole interval lies above "
      "1 + PCT/100 and the test is significant, passes it when the whole interval lies at or "
      "below, and else calls it inconclusive, as it does rows of one process or of a disturbed "
      "machine. --run OLD NEW runs the two binaries' benches alternately, A B B A ..., --rounds "
      "times each, every run a process of its own, then compares them. Exit 0: compared (with "
      "--fail-above: every row passed). 1: a row failed the gate, or no row was compared. 2: a "
      "file is missing, not JSON or not a bench file, files of two machines without "
      "--across-machines, or bad options; nothing is written. 3: the gate was inconclusive (no "
      "row failed, one could not be decided). See docs/harness.md, \"Comparing bench files\".";
  sub->add("FILES", &a->files, "Bench files, the first the baseline (A), then B, C, ...")
      .type("FILE")
      .path_kind(PathKind::InputFile);
  sub->add("--fail-above", &a->fail_above,
           "Exit 1 when a row is slower than the baseline by more than PCT "
           "percent with its whole 95% interval; 3 when a row cannot be "
           "decided (a CI regression gate)")
      .type("PCT")
      .real_in(0, 1000);
  sub->flag("--across-machines", a->across_machines,
            "Compare files measured on different machines (refused otherwise)");
  sub->add("--run", &a->run,
           "Two pxflow binaries, the baseline first: run their benches "
           "alternately and compare them (a pull request's gate)")
      .type("OLD NEW")
      .value_count(2, 2)
      .path_kind(PathKind::InputFile);
  sub->add("--rounds", &a->rounds,
           "With --run: bench processes of each binary (A B, B A, ...); 4 at least for a "
           "95% interval")
      .type("N")
      .in_range(1, 1000)
      .with_default();
  sub->add("--bench-args", &a->bench_args,
           "With --run: the bench options of every process, e.g. \"--backends cpu --batch "
           "256 --min-time 0.2\" (--min-time is per process here)")
      .type("\"OPTIONS\"");
  sub->add("--out", &a->out_dir,
           "Folder to write compare.json and compare.csv into (created when missing); "
           "with --run also bench-A.json and bench-B.json")
      .type("DIR")
      .path_kind(PathKind::OwnedFolder);
  return {sub, [a] { return run_compare(*a); }, kCompareExamples, {"{BENCH} {BENCH2}"}};
}

}  // namespace pxflow::cli
