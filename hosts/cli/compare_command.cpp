// pxflow compare: bench files of other machines, builds or drivers, row by row against the first
// (docs/harness.md, "Comparing bench files"); a CI regression gate with --fail-above.
#include <filesystem>
#include <iostream>

#include "bench_compare.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "input_file.hpp"
#include "json_document.hpp"
#include "output_plan.hpp"
#include "owned_folder.hpp"
#include "path_options.hpp"

namespace pxflow::cli {
namespace {

struct CompareArgs {
  std::vector<std::string> files;
  std::string out_dir;
  double fail_above = -1;  // -1: not a gate
};

// Each file read and checked before anything is written: a wrong one is one line, exit 2.
std::vector<BenchFile> read_bench_files(const std::vector<std::string>& paths) {
  if (paths.size() < 2)
    throw InputError(
        "compare needs two bench files or more, the first the baseline (see pxflow "
        "compare --help)");
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

// The list of the files a compare folder holds (io/owned_folder.hpp).
constexpr const char* kCompareManifest = ".pxflow-compare";

int run_compare(const CompareArgs& a) {
  OutputPlan plan;
  plan.read_all(a.files);
  OutputFile *json_out = nullptr, *csv_out = nullptr, *listed = nullptr;
  if (!a.out_dir.empty()) {
    namespace fs = std::filesystem;
    plan.make_folder("--out", a.out_dir, kCompareManifest);
    json_out = &plan.file("--out", (fs::path(a.out_dir) / "compare.json").string());
    csv_out = &plan.file("--out", (fs::path(a.out_dir) / "compare.csv").string());
    listed = &plan.file("--out", (fs::path(a.out_dir) / kCompareManifest).string());
  }
  const std::vector<BenchFile> files = read_bench_files(a.files);
  plan.prepare();
  const BenchComparison c = compare_bench_files(files);
  print_comparison(c, std::cout);
  if (json_out) {
    json_out->write(json_document(comparison_json(c)));
    csv_out->write(comparison_csv(c));
    listed->write(manifest_text({"compare.json", "compare.csv"}));
    std::cout << "wrote " << a.out_dir << "/compare.json and compare.csv\n";
  }
  if (a.fail_above < 0) return 0;
  int slower = 0;
  for (const CompareRow& r : c.rows) slower += slower_beyond(r, a.fail_above);
  std::cout << "pxflow compare: " << slower << " row" << (slower == 1 ? "" : "s")
            << " significantly slower by more than " << a.fail_above << " %\n";
  return slower > 0 ? 1 : 0;
}

}  // namespace

// What --help and the man page show under Examples (the command line after "pxflow ").
const std::vector<std::string> kCompareExamples = {
    "compare main.json today.json --fail-above 5  # exit 1 on a significant slowdown over 5 %",
    "compare laptop.json h200.json --out cmp  # cmp/compare.json and cmp/compare.csv",
};

Command add_compare_command(CLI::App& app) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* sub = app.add_subcommand(
      "compare",
      "Compare bench files (pxflow bench --json) of other machines, builds or drivers with the "
      "first: per backend and point, the ratio of medians and a Mann-Whitney U test");
  sub->footer(
      "Rows are compared when backend, point and clock are equal (the thread count only in the "
      "thread sweep); a row timed by another clock is listed as not comparable. ratio = "
      "median / baseline median (> 1: slower), with the interval the two medians' 95% intervals "
      "bound. A change is significant when the U test on the two rows' samples gives p < 0.05 "
      "(Google Benchmark's compare.py); an exact clock (a deterministic model) changes whenever "
      "its count does. Exit 0: compared (no --fail-above, or no row over it). 1: --fail-above "
      "PCT and a row significantly slower by more than PCT %. 2: a file is missing, not JSON or "
      "not a bench file; nothing is written. See docs/harness.md, \"Comparing bench files\".");
  declare_path(
      sub->add_option("FILES", a->files, "Bench files, the first the baseline (A), then B, C, ...")
          ->type_name("FILE"),
      PathKind::InputFile)
      ->required();
  sub->add_option("--fail-above", a->fail_above,
                  "Exit 1 when a row is significantly slower than the baseline by more than PCT "
                  "percent (a CI regression gate)")
      ->type_name("PCT")
      ->check(CLI::Range(0.0, 1e6));
  sub->add_option("--out", a->out_dir,
                  "Folder to write compare.json and compare.csv into (created when missing)")
      ->type_name("DIR");
  declare_path(sub->get_option("--out"), PathKind::OwnedFolder);
  return {sub, [a] { return run_compare(*a); }, kCompareExamples, {"{BENCH} {BENCH2}"}};
}

}  // namespace pxflow::cli
