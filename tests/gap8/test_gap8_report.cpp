// pxflow report's GAP8 section: the paper's tables with the model beside them, a speed-up chart,
// and the raw figures in results.json; left out for reports about other backends or on request.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bad_input.hpp"
#include "results_files.hpp"
#include "run_program.hpp"

namespace pxflow::test {
namespace {

RunResult report(const TempDir& dir, const std::string& out, std::vector<std::string> extra) {
  std::vector<std::string> args{
      "report",           "--out",        dir.path(out),      "--check-json",
      dir.path("c.json"), "--bench-json", dir.path("b.json"), "--no-accuracy"};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_pxflow(args);
}

}  // namespace

TEST_CASE("pxflow report shows the GAP8 model beside the paper's Tables I-III", "[gap8][report]") {
  TempDir dir;
  make_small_results(dir);
  const RunResult r = report(dir, "all", {});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const std::string md = slurp(dir.path("all/report.md"));
  for (const char* heading : {"## GAP8 model: Table I:", "## GAP8 model: Table II:",
                              "## GAP8 model: Table III:", "## GAP8 model: every core count"})
    CHECK(md.find(heading) != std::string::npos);
  CHECK(md.find("`pxflow gap8 --cores 1-8`") != std::string::npos);
  CHECK(md.find("| 4-byte SAD ops | original | 91520 | 91520 | +0.0% |") != std::string::npos);
  CHECK(md.find("| cycles, 1 core | original |") != std::string::npos);
  CHECK(md.find("| cycles, 2 cores |") == std::string::npos);  // the paper's tables: 1 and 8 cores
  CHECK(md.find("| local | 5 |") != std::string::npos);        // every count in the last table

  const auto j = nlohmann::json::parse(slurp(dir.path("all/results.json")));
  CHECK(j["commands"]["gap8"] == "pxflow gap8 --cores 1-8");
  const auto& eight = j["gap8"]["variants"]["original"]["8"];
  CHECK(eight["paper"]["cycles"] == 99000.0);
  CHECK(eight["speedup"].get<double>() > 1.0);
  CHECK(eight["speedup"].get<double>() <= eight["amdahl_limit"].get<double>());
  // The table shows the figure of the JSON.
  char cycles[64];
  std::snprintf(cycles, sizeof cycles, "| cycles, 8 cores | original | %.1fk |",
                eight["cycles"].get<double>() / 1000);
  CHECK(md.find(cycles) != std::string::npos);
  const std::string html = slurp(dir.path("all/report.html"));
  CHECK(html.find("<title>GAP8 model: speed-up over 1 core</title>") != std::string::npos);
}

TEST_CASE("pxflow report leaves the GAP8 section out for other backends or with --no-gap8",
          "[gap8][report]") {
  TempDir dir;
  make_small_results(dir);
  for (const auto& extra : {std::vector<std::string>{"--backends", "ref-original"},
                            std::vector<std::string>{"--no-gap8"}}) {
    const RunResult r = report(dir, "without", extra);
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(slurp(dir.path("without/report.md")).find("## GAP8 model") == std::string::npos);
    CHECK(nlohmann::json::parse(slurp(dir.path("without/results.json")))["gap8"].is_null());
  }
}

TEST_CASE("pxflow report charts the GAP8 rows by the model's clock, apart from the host's",
          "[gap8][report]") {
  TempDir dir;
  make_small_results(dir);
  REQUIRE(run_pxflow({"bench", "--backends", "gap8-fast,ref-original", "--batch", "1", "--min-time",
                      "0", "--json", dir.path("b.json")})
              .exit_code == 0);
  nlohmann::json bench = nlohmann::json::parse(slurp(dir.path("b.json")));
  for (auto& r : bench["rows"]) r["sweep"] = "batch";  // as the default sweeps name them
  dir.write("b.json", bench.dump());
  const RunResult r = report(dir, "r", {"--backends", "ref-original,gap8-fast"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(slurp(dir.path("r/results.json")));
  bool host_chart = false, model_chart = false, speedup_chart = false;
  for (const auto& s : j["sections"])
    for (const auto& c : s["charts"]) {
      const std::string title = c["title"];
      std::string labels;
      for (const auto& b : c["bars"]) labels += b["label"].get<std::string>() + ";";
      for (const auto& se : c["series"]) labels += se["name"].get<std::string>() + ";";
      if (title.find("by the host clock") != std::string::npos) {
        host_chart = true;
        CHECK(labels == "ref-original;");  // never the model's frames/s beside the host's
      }
      if (title.find("exact model clock") != std::string::npos && c["kind"] == "bar") {
        model_chart = true;
        CHECK(labels == "gap8-fast (batch 1);");
      }
      if (title == "GAP8 model: speed-up over 1 core") {
        speedup_chart = true;
        CHECK(c["x_axis"]["log"] == false);  // 1..8 cores, every one labelled
        CHECK(c["x_axis"]["integer"] == true);
        CHECK(c["y_axis"]["log"] == false);
      }
    }
  CHECK(host_chart);
  CHECK(model_chart);
  CHECK(speedup_chart);
  const std::string md = slurp(dir.path("r/report.md"));
  CHECK(md.find("| gap8-fast (model clock) |") != std::string::npos);  // the batch sweep's row
  // The model's version is in the provenance, from the backend itself.
  bool described = false;
  for (const auto& b : j["provenance"]["backends"])
    if (b["backend"] == "gap8-fast")
      described = b["driver"].get<std::string>().rfind("gap8_model ", 0) == 0;
  CHECK(described);
}

}  // namespace pxflow::test

namespace pxflow::test {

TEST_CASE("gap8 at another profile shows no paper figures beside the model", "[gap8]") {
  const auto r =
      run_pxflow({"gap8", "--profile", "px4flow-head", "--variant", "original", "--cores", "1"});
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("no paper figure is shown") != std::string::npos);
  CHECK(r.out.find("717.2k") == std::string::npos);  // the paper's 1-core cycles
}

}  // namespace pxflow::test

namespace pxflow::test {

TEST_CASE("bench times a GAP8 row by its exact model clock from the one checked run", "[gap8]") {
  TempDir dir;
  const auto r = run_pxflow({"bench", "--backends", "gap8-fast", "--batch", "1", "--min-time", "0",
                             "--json", dir.path("b.json")});
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(slurp(dir.path("b.json")));
  REQUIRE(j["rows"].size() == 1);  // no host-clock row: the host's time is the simulation's
  const auto& row = j["rows"][0];
  CHECK(row["source"] == "gap8-model-cycles");
  CHECK(row["repeats"] == 1);
  CHECK(row["cycles_per_frame"].get<double>() > 10000);
  CHECK(row["note"].get<std::string>().find("host simulation") != std::string::npos);
}

TEST_CASE("report: an accuracy backend that cannot take the accuracy pairs is refused first",
          "[gap8][report]") {
  TempDir dir;
  // gap8-fast keeps a frame in the 64 KiB L1: the accuracy table's 320x240 pairs do not fit.
  // Refused before the check and the bench run, and before the folder is made.
  require_bad_input({"report", "--out", dir.path("r"), "--backends", "ref-original", "--backend",
                     "gap8-fast", "--quick"},
                    "backend gap8-fast does not support this problem");
  CHECK(slurp(dir.path("r/report.md")).empty());
}

}  // namespace pxflow::test
