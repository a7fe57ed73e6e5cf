// pxflow compare and report --bench-json A B (docs/harness.md, "Comparing bench files"): a
// regression planted in a copy of a real bench file is flagged and fails --fail-above only when
// its whole interval is above it; identical files never fail; rows of one process, or of a
// disturbed machine, are inconclusive (exit 3), never a verdict; rows whose work differs (clock,
// --set, threads) are never paired; files of two machines need --across-machines; a comparison of
// nothing exits 1; a wrong file is one line and exit 2.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "results_files.hpp"
#include "run_program.hpp"

namespace pxflow::test {
namespace {

using nlohmann::json;

// Five process medians 1 % apart around `m`, `factor` times slower.
void set_processes(json& row, double m, double factor) {
  row["processes"] = 5;
  row["process_medians_ns_per_frame"] = json::array();
  for (double f : {0.98, 0.99, 1.0, 1.01, 1.02})
    row["process_medians_ns_per_frame"].push_back(m * f * factor);
  row["median_ns_per_frame"] = m * factor;
  row["median_ci_low_ns"] = row["min_ns_per_frame"] = m * 0.98 * factor;
  row["median_ci_high_ns"] = row["max_ns_per_frame"] = m * 1.02 * factor;
}

// A real bench file of two rows (ref-original and ref-local at batch 1), as a.json in `dir`, its
// rows then given five process medians 1 % apart: what is tested is the comparison, not how quiet
// this shared machine was while it measured (its "machine" is set quiet too).
json make_baseline(const TempDir& dir) {
  const RunResult r =
      run_pxflow({"bench", "--backends", "ref-original,ref-local", "--batch", "1", "--min-time",
                  "0", "--processes", "1", "--no-bound", "--json", dir.path("a.json")});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  json a = json::parse(slurp(dir.path("a.json")));
  REQUIRE(a["rows"].size() == 2);
  for (json& row : a["rows"]) set_processes(row, row["median_ns_per_frame"].get<double>(), 1.0);
  a["machine"]["disturbed"] = "";
  dir.write("a.json", a.dump(2));
  return a;
}

// `a` with its first row `factor` times slower, as `name`.
void write_slower_copy(const TempDir& dir, json a, double factor, const std::string& name) {
  json& row = a["rows"][0];
  set_processes(row, row["median_ns_per_frame"].get<double>(), factor);
  dir.write(name, a.dump(2));
}

const json* compared_row(const json& c, const std::string& backend) {
  for (const auto& r : c["rows"])
    if (r["backend"] == backend) return &r;
  return nullptr;
}

RunResult compare(const TempDir& dir, const std::string& b, std::vector<std::string> more = {}) {
  std::vector<std::string> args{"compare", dir.path("a.json"), dir.path(b)};
  args.insert(args.end(), more.begin(), more.end());
  return run_pxflow(args);
}

}  // namespace

TEST_CASE("compare: a row planted 20 % slower is flagged, and fails --fail-above 10", "[compare]") {
  TempDir dir;
  const json a = make_baseline(dir);
  write_slower_copy(dir, a, 1.2, "b.json");
  const RunResult r = compare(dir, "b.json", {"--out", dir.path("cmp")});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);  // no gate without --fail-above
  const json c = json::parse(slurp(dir.path("cmp/compare.json")));
  const json* slow = compared_row(c, "ref-original");
  REQUIRE(slow);
  CHECK((*slow)["verdict"] == "slower");
  CHECK((*slow)["ratio"].get<double>() == Approx(1.2));
  CHECK((*slow)["p_value"].get<double>() < 0.05);
  CHECK((*slow)["processes"] == 5);
  CHECK((*slow)["ratio_ci_low"].get<double>() <= 1.2);
  CHECK((*slow)["ratio_ci_low"].get<double>() > 1.1);
  CHECK((*slow)["ratio_ci_high"].get<double>() >= 1.2);
  const json* same = compared_row(c, "ref-local");
  REQUIRE(same);
  CHECK((*same)["verdict"] == "not significant");
  CHECK((*same)["p_value"] == 1.0);
  // Each file named by its provenance: machine and build.
  REQUIRE(c["files"].size() == 2);
  CHECK(c["files"][1].get<std::string>().find("pxflow 0.") != std::string::npos);
  CHECK(slurp(dir.path("cmp/compare.csv")).rfind("file,backend,sweep,", 0) == 0);

  const RunResult gate = compare(dir, "b.json", {"--fail-above", "10"});
  INFO(gate.out);
  CHECK(gate.exit_code == 1);
  CHECK(gate.out.find("2 rows gated at 10 %: 1 failed, 0 inconclusive, 1 passed (exit 1)") !=
        std::string::npos);
  // 25 %: the whole interval lies below 1.25: passed. 20 %: the interval holds 1.2: undecided.
  CHECK(compare(dir, "b.json", {"--fail-above", "25"}).exit_code == 0);
  const RunResult undecided = compare(dir, "b.json", {"--fail-above", "20"});
  CHECK(undecided.exit_code == 3);
  CHECK(undecided.out.find("inconclusive: its interval [") != std::string::npos);
}

TEST_CASE("compare: identical files are never flagged, and pass a 5 % gate", "[compare]") {
  TempDir dir;
  make_baseline(dir);
  dir.write("copy.json", slurp(dir.path("a.json")));
  const RunResult r = compare(dir, "copy.json", {"--fail-above", "5", "--out", dir.path("cmp")});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  const json c = json::parse(slurp(dir.path("cmp/compare.json")));
  REQUIRE(c["rows"].size() == 2);
  for (const auto& row : c["rows"]) {
    CHECK(row["verdict"] == "not significant");
    CHECK(row["gate"] == "pass");
  }
}

// The false alarm of 1261786: two runs of one build, samples of one process each, 1.91x apart
// and "p = 0.0000". Samples inside one process are not independent runs: no verdict.
TEST_CASE("compare: rows of one process are inconclusive, never a failure", "[compare]") {
  TempDir dir;
  json a = make_baseline(dir);
  for (json& row : a["rows"]) {
    const double m = row["median_ns_per_frame"].get<double>();
    row.erase("processes"), row.erase("process_medians_ns_per_frame");
    row["samples_ns_per_frame"] = {m * 0.99, m, m * 1.01, m, m, m * 1.005, m * 0.995};
  }
  dir.write("a.json", a.dump());
  for (json& row : a["rows"])
    for (auto& x : row["samples_ns_per_frame"]) x = x.get<double>() * 1.91;
  for (json& row : a["rows"])
    row["median_ns_per_frame"] = row["median_ns_per_frame"].get<double>() * 1.91;
  dir.write("b.json", a.dump());
  const RunResult r = compare(dir, "b.json", {"--fail-above", "5"});
  INFO(r.out);
  CHECK(r.exit_code == 3);
  CHECK(r.out.find("one process") != std::string::npos);
  CHECK(r.out.find(" 0 failed, 2 inconclusive") != std::string::npos);
}

TEST_CASE("compare: a wide interval holding 1 never fails, whatever the median ratio",
          "[compare]") {
  TempDir dir;
  json a = make_baseline(dir);
  json b = a;
  const double m = a["rows"][0]["median_ns_per_frame"].get<double>();
  a["rows"][0]["process_medians_ns_per_frame"] = {m * 0.5, m * 0.8, m, m * 1.5, m * 2.5};
  b["rows"][0]["process_medians_ns_per_frame"] = {m * 0.6, m * 1.0, m * 1.2, m * 1.8, m * 3.0};
  b["rows"][0]["median_ns_per_frame"] = m * 1.2;
  dir.write("a.json", a.dump());
  dir.write("b.json", b.dump());
  const RunResult r = compare(dir, "b.json", {"--fail-above", "5", "--out", dir.path("cmp")});
  INFO(r.out);
  CHECK(r.exit_code == 3);
  const json c = json::parse(slurp(dir.path("cmp/compare.json")));
  const json* row = compared_row(c, "ref-original");
  REQUIRE(row);
  CHECK((*row)["ratio_ci_low"].get<double>() < 1);
  CHECK((*row)["gate"] == "inconclusive");
  CHECK((*row)["verdict"] == "not significant");
}

TEST_CASE("compare: a disturbed machine makes the gate inconclusive", "[compare]") {
  TempDir dir;
  json a = make_baseline(dir);
  write_slower_copy(dir, a, 1.5, "b.json");
  json b = json::parse(slurp(dir.path("b.json")));
  b["machine"]["disturbed"] = "other processes took 60 % (planted)";
  dir.write("b.json", b.dump());
  const RunResult r = compare(dir, "b.json", {"--fail-above", "5"});
  INFO(r.out);
  CHECK(r.exit_code == 3);
  CHECK(r.out.find("B was measured on a disturbed machine") != std::string::npos);
}

TEST_CASE("compare: rows whose work differs are never paired, and say what differs", "[compare]") {
  TempDir dir;
  json a = make_baseline(dir);
  SECTION("another clock") {
    a["rows"][0]["source"] = "opencl-event-profiling";
    dir.write("b.json", a.dump());
    const RunResult r = compare(dir, "b.json", {"--out", dir.path("cmp")});
    INFO(r.out << r.err);
    CHECK(r.exit_code == 0);
    const json c = json::parse(slurp(dir.path("cmp/compare.json")));
    CHECK_FALSE(compared_row(c, "ref-original"));
    CHECK(compared_row(c, "ref-local"));
    CHECK(r.out.find("not comparable: clock host-steady-clock+tsc in A, opencl-event-profiling "
                     "in B") != std::string::npos);
  }
  SECTION("--set blocks=2, and --threads 1: nothing compared, exit 1") {
    a["rows"][0]["params"]["blocks"] = 2;
    a["rows"][1]["threads"] = 1, a["rows"][1]["threads_requested"] = 1;
    dir.write("b.json", a.dump());
    const RunResult r = compare(dir, "b.json", {"--fail-above", "5"});
    INFO(r.out << r.err);
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("not comparable: blocks 8 in A, 2 in B") != std::string::npos);
    CHECK(r.out.find("not comparable: threads") != std::string::npos);
    CHECK(r.out.find("no row was compared (exit 1)") != std::string::npos);
  }
  SECTION("a point the baseline measured and the other file did not") {
    json failed = a;
    for (const char* key : {"median_ns_per_frame", "samples_ns_per_frame"})
      failed["rows"][1].erase(key);
    failed["rows"][1]["note"] = "failed: planted";
    dir.write("failed.json", failed.dump());
    const RunResult missing = compare(dir, "failed.json", {"--fail-above", "10"});
    INFO(missing.out);
    CHECK(missing.exit_code == 0);
    CHECK(missing.out.find("B: ref-local custom batch=1 64x64 S=4") != std::string::npos);
    CHECK(missing.out.find("measured in A only (B's note: failed: planted)") != std::string::npos);
  }
}

TEST_CASE("compare: files of two machines only with --across-machines, which says so",
          "[compare]") {
  TempDir dir;
  json a = make_baseline(dir);
  a["provenance"]["machine"]["host"] = "far-away";
  a["provenance"]["machine"]["cpu"] = "Planted CPU 9000";
  for (json& row : a["rows"]) row["device"] = "elsewhere";
  dir.write("far.json", a.dump());
  const RunResult refused = compare(dir, "far.json");
  CHECK(refused.exit_code == 2);
  CHECK(refused.err_lines() == 1);
  CHECK(refused.err.find("--across-machines") != std::string::npos);
  const RunResult r = compare(dir, "far.json", {"--across-machines", "--out", dir.path("cmp")});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("across machines: A (") != std::string::npos);
  CHECK(r.out.find("far-away (Planted CPU 9000)") != std::string::npos);
  const json c = json::parse(slurp(dir.path("cmp/compare.json")));
  CHECK(c["rows"].size() == 2);  // the device differs, as it must across machines
  CHECK(c["across_machines"].get<std::string>().find("far-away") != std::string::npos);
}

TEST_CASE("compare: a wrong file is one line and exit 2, and nothing is written", "[compare]") {
  TempDir dir;
  make_baseline(dir);
  dir.write("text.json", "not json");
  dir.write("check.json", R"({"backends": [], "passed": 1, "failed": 0})");
  for (const std::vector<std::string>& files : {std::vector<std::string>{dir.path("a.json")},
                                                {dir.path("a.json"), dir.path("missing.json")},
                                                {dir.path("a.json"), dir.path("text.json")},
                                                {dir.path("a.json"), dir.path("check.json")}}) {
    std::vector<std::string> args{"compare"};
    args.insert(args.end(), files.begin(), files.end());
    args.insert(args.end(), {"--out", dir.path("cmp")});
    const RunResult r = run_pxflow(args);
    INFO(r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err_lines() == 1);
    CHECK(r.err.rfind("pxflow: error: ", 0) == 0);
    CHECK(slurp(dir.path("cmp/compare.json")).empty());
  }
}

TEST_CASE("report --bench-json A B: a section per compared file and one chart across them",
          "[compare][report]") {
  TempDir dir;
  make_small_results(dir);  // c.json (the check) and b.json, replaced below
  json a = make_baseline(dir);
  write_slower_copy(dir, a, 1.2, "b.json");
  a["machine"]["disturbed"] = "a disturbance the test planted";  // warned about, first screen
  dir.write("a.json", a.dump());
  const RunResult r =
      run_pxflow({"report", "--out", dir.path("r"), "--check-json", dir.path("c.json"),
                  "--bench-json", dir.path("a.json"), dir.path("b.json"), "--no-accuracy",
                  "--backends", "ref-original,ref-local"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(slurp(dir.path("r/results.json")));
  CHECK(j["comparison"]["rows"].size() == 2);
  bool chart = false, flagged = false;
  for (const auto& s : j["sections"]) {
    if (s["key"] == "comparison") chart = s["charts"].size() == 1;
    if (s["key"] == "comparison-b")
      for (const auto& row : s["rows"])
        flagged |= row[0] == "ref-original" && row[7] == "inconclusive";
  }
  CHECK(chart);
  CHECK(flagged);
  const std::string html = slurp(dir.path("r/report.html"));
  CHECK(html.find("<h2 id='comparison-b'>") != std::string::npos);
  CHECK(html.find("<strong>Warning: the bench ran on a disturbed machine (a disturbance the test "
                  "planted)") != std::string::npos);
  CHECK(html.find("A was measured on a disturbed machine") != std::string::npos);
  REQUIRE(!j["comparison"]["warnings"].empty());  // B too, when this machine was busy
  CHECK(j["comparison"]["warnings"][0].get<std::string>().rfind("A was measured", 0) == 0);
}

}  // namespace pxflow::test
