// pxflow compare and report --bench-json A B: a regression planted in a copy of a real bench
// file is flagged (and fails --fail-above), identical files never are, rows of other clocks are
// not compared, and a wrong file is one line and exit 2 (docs/harness.md, "Comparing bench
// files").
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "results_files.hpp"
#include "run_program.hpp"

namespace pxflow::test {
namespace {

using nlohmann::json;

// A real bench file of two rows (ref-original and ref-local at batch 1, 5 samples each), as
// a.json in `dir`. The first row's samples are then set 1 % apart around its median: what is
// tested is the comparison, not how quiet this shared machine was while it measured.
json make_baseline(const TempDir& dir) {
  const RunResult r = run_pxflow({"bench", "--backends", "ref-original,ref-local", "--batch", "1",
                                  "--min-time", "0", "--json", dir.path("a.json")});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  json a = json::parse(slurp(dir.path("a.json")));
  REQUIRE(a["rows"].size() == 2);
  json& row = a["rows"][0];
  const double m = row["median_ns_per_frame"].get<double>();
  row["samples_ns_per_frame"] = {m * 0.98, m * 0.99, m, m * 1.01, m * 1.02};
  row["median_ci_low_ns"] = row["min_ns_per_frame"] = m * 0.98;
  row["median_ci_high_ns"] = row["max_ns_per_frame"] = m * 1.02;
  dir.write("a.json", a.dump(2));
  return a;
}

// `a` with every sample (and figure) of its first row `factor` times slower, as `name`.
void write_slower_copy(const TempDir& dir, json a, double factor, const std::string& name) {
  json& row = a["rows"][0];
  for (auto& s : row["samples_ns_per_frame"]) s = s.get<double>() * factor;
  for (const char* key : {"median_ns_per_frame", "median_ci_low_ns", "median_ci_high_ns",
                          "min_ns_per_frame", "max_ns_per_frame"})
    row[key] = row[key].get<double>() * factor;
  dir.write(name, a.dump(2));
}

const json* compared_row(const json& c, const std::string& backend) {
  for (const auto& r : c["rows"])
    if (r["backend"] == backend) return &r;
  return nullptr;
}

}  // namespace

TEST_CASE("compare: a row planted 20 % slower is flagged, and fails --fail-above 10", "[compare]") {
  TempDir dir;
  const json a = make_baseline(dir);
  write_slower_copy(dir, a, 1.2, "b.json");
  const RunResult r =
      run_pxflow({"compare", dir.path("a.json"), dir.path("b.json"), "--out", dir.path("cmp")});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);  // no gate without --fail-above
  const json c = json::parse(slurp(dir.path("cmp/compare.json")));
  const json* slow = compared_row(c, "ref-original");
  REQUIRE(slow);
  CHECK((*slow)["verdict"] == "slower");
  CHECK((*slow)["ratio"].get<double>() == Approx(1.2));
  CHECK((*slow)["p_value"].get<double>() < 0.05);
  CHECK((*slow)["ratio_ci_low"].get<double>() <= 1.2);
  CHECK((*slow)["ratio_ci_high"].get<double>() >= 1.2);
  const json* same = compared_row(c, "ref-local");
  REQUIRE(same);
  CHECK((*same)["verdict"] == "same");
  CHECK((*same)["p_value"] == 1.0);
  // Each file named by its provenance: machine and build.
  REQUIRE(c["files"].size() == 2);
  CHECK(c["files"][1].get<std::string>().find("pxflow 0.") != std::string::npos);
  CHECK(r.out.find("slower") != std::string::npos);
  // The CSV: a header and a line per compared row.
  CHECK(slurp(dir.path("cmp/compare.csv")).rfind("file,backend,sweep,", 0) == 0);

  const RunResult gate =
      run_pxflow({"compare", dir.path("a.json"), dir.path("b.json"), "--fail-above", "10"});
  CHECK(gate.exit_code == 1);
  CHECK(gate.out.find("1 row significantly slower by more than 10 %") != std::string::npos);
  CHECK(run_pxflow({"compare", dir.path("a.json"), dir.path("b.json"), "--fail-above", "25"})
            .exit_code == 0);
}

TEST_CASE("compare: identical files are never flagged", "[compare]") {
  TempDir dir;
  make_baseline(dir);
  dir.write("copy.json", slurp(dir.path("a.json")));
  const RunResult r = run_pxflow({"compare", dir.path("a.json"), dir.path("copy.json"),
                                  "--fail-above", "0", "--out", dir.path("cmp")});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  const json c = json::parse(slurp(dir.path("cmp/compare.json")));
  REQUIRE(c["rows"].size() == 2);
  for (const auto& row : c["rows"]) CHECK(row["verdict"] == "same");
}

TEST_CASE("compare: rows of another clock are listed as not comparable", "[compare]") {
  TempDir dir;
  json a = make_baseline(dir);
  a["rows"][0]["source"] = "opencl-event-profiling";
  dir.write("other-clock.json", a.dump());
  const RunResult r = run_pxflow(
      {"compare", dir.path("a.json"), dir.path("other-clock.json"), "--out", dir.path("cmp")});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  const json c = json::parse(slurp(dir.path("cmp/compare.json")));
  CHECK_FALSE(compared_row(c, "ref-original"));
  CHECK(compared_row(c, "ref-local"));
  REQUIRE(c["not_compared"].size() == 1);
  CHECK(c["not_compared"][0].get<std::string>().find("not comparable") != std::string::npos);

  // A point the baseline measured and the other file did not (its row failed there): listed.
  json failed = json::parse(slurp(dir.path("a.json")));
  for (const char* key : {"median_ns_per_frame", "samples_ns_per_frame"})
    failed["rows"][1].erase(key);
  failed["rows"][1]["note"] = "failed: planted";
  dir.write("failed.json", failed.dump());
  const RunResult missing =
      run_pxflow({"compare", dir.path("a.json"), dir.path("failed.json"), "--fail-above", "10"});
  INFO(missing.out);
  CHECK(missing.exit_code == 0);
  CHECK(missing.out.find("B: ref-local custom batch=1 64x64 S=4") != std::string::npos);
  CHECK(missing.out.find("measured in A only (B's note: failed: planted)") != std::string::npos);
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
      for (const auto& row : s["rows"]) flagged |= row[0] == "ref-original" && row[7] == "slower";
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
