// A check a signal stopped keeps what it checked, and `pxflow check --resume FILE` finishes it
// into the uninterrupted run's result: the same verdict, counts, states and failure lines
// (docs/harness.md, "Stopping and resuming a campaign"). The stops come from the test-only
// PXFLOW_TEST_STOP_AFTER_CASES=N (the check raises SIGINT on itself after N cases);
// test_resume_signals.cpp sends real signals.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

#include "build_paths.hpp"
#include "json_file.hpp"
#include "run_program.hpp"

using nlohmann::json;
using pxflow::test::read_json;
using pxflow::test::run_program;
using pxflow::test::RunResult;
using pxflow::test::slurp;
using pxflow::test::TempDir;

namespace {

// pxflow with the test rows, stopped by itself after `stop_after` cases (0: never).
RunResult test_rows_run(std::vector<std::string> args, int stop_after = 0) {
  if (stop_after == 0) return run_program(build_paths::pxflow_with_test_rows, args);
  args.insert(args.begin(), {"PXFLOW_TEST_STOP_AFTER_CASES=" + std::to_string(stop_after),
                             build_paths::pxflow_with_test_rows});
  return run_program("/usr/bin/env", args);
}

// The file without its times: what an uninterrupted and a resumed run must agree on.
json without_times(json j) {
  j.erase("seconds");
  for (json& b : j["backends"]) b.erase("seconds");
  return j;
}

std::vector<std::string> with(std::vector<std::string> args,
                              const std::vector<std::string>& extra) {
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

// Runs `check ARGS --json FILE` whole, then again stopped after `first` cases, resumed and
// stopped after `second` more, and resumed to the end; the same FILE each time, so that the
// recorded command is the same. Returns {whole, resumed}.
std::pair<json, json> whole_and_resumed(const TempDir& dir, const std::vector<std::string>& args,
                                        int first, int second, int expected_exit) {
  const std::string file = dir.path("ci.json");
  const std::vector<std::string> run = with(with({"check"}, args), {"--json", file});
  const RunResult whole = test_rows_run(run);
  INFO(whole.out << whole.err);
  REQUIRE(whole.exit_code == expected_exit);
  const json whole_json = read_json(file);
  CHECK(whole_json["complete"] == true);

  const RunResult stopped = test_rows_run(run, first);
  INFO(stopped.out << stopped.err);
  REQUIRE(stopped.exit_code == 130);
  CHECK(stopped.err.find("pxflow: interrupted: SIGINT after " + std::to_string(first) + " of ") !=
        std::string::npos);
  CHECK(stopped.err.find("pxflow check --resume " + file + " goes on") != std::string::npos);
  const json part = read_json(file);
  CHECK(part["complete"] == false);
  CHECK(part["verdict"] == "incomplete");
  CHECK(part["cases"] == first);
  CHECK(part["cases_total"] == whole_json["cases_total"]);

  const RunResult again = test_rows_run({"check", "--resume", file}, second);
  INFO(again.out << again.err);
  REQUIRE(again.exit_code == 130);
  CHECK(read_json(file)["cases"] == first + second);  // the union of both runs' work

  const RunResult rest = test_rows_run({"check", "--resume", file});
  INFO(rest.out << rest.err);
  CHECK(rest.exit_code == expected_exit);
  return {whole_json, read_json(file)};
}

}  // namespace

TEST_CASE("resume: a fuzz campaign stopped twice and resumed is the uninterrupted run",
          "[resume]") {
  TempDir dir;
  // 2000 pairs: 8 batches of 256 (the last 208); test-bitflip fails every batch, test-unavailable
  // cannot run, test-small-only is n/a on nothing here (64x64 pairs).
  const auto [whole, resumed] =
      whole_and_resumed(dir,
                        {"--backends", "ref-original,ref-local,test-bitflip,test-unavailable",
                         "--cases", "2000", "--seed", "7"},
                        3, 2, 1);
  CHECK(without_times(resumed) == without_times(whole));
  CHECK(whole["verdict"] == "failed");
  CHECK(whole["cases"] == 8);
  CHECK(whole["backends"][2]["failed"] == 8);
  CHECK(whole["backends"][3]["state"] == "skipped");
}

TEST_CASE("resume: the fixed corpus with n/a cases and a required skip", "[resume]") {
  TempDir dir;
  const auto [whole, resumed] =
      whole_and_resumed(dir,
                        {"--backends", "ref-original,ref-local,test-small-only,test-unavailable",
                         "--require", "test-unavailable", "--generated-only"},
                        4, 5, 1);
  CHECK(without_times(resumed) == without_times(whole));
  CHECK(whole["backends"][2]["not_applicable"].get<long>() > 0);
  CHECK(whole["backends"][3]["state"] == "failed");
}

TEST_CASE("resume: the stopped file names its campaign, its backends are incomplete", "[resume]") {
  TempDir dir;
  const std::string file = dir.path("ci.json");
  const RunResult r = test_rows_run({"check", "--backends", "ref-original,ref-local", "--cases",
                                     "2000", "--seed", "7", "--json", file},
                                    2);
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 130);
  CHECK(r.out.find("incomplete: stopped after 2 cases of 8") != std::string::npos);
  const json j = read_json(file);
  CHECK(j["seed"] == 7);
  CHECK(j["campaign"]["fuzz_pairs"] == 2000);
  CHECK(j["campaign"]["backends"] == json({"ref-original", "ref-local"}));
  CHECK(j["shard"]["first_case"] == 0);
  CHECK(j["shard"]["end_case"] == 8);
  CHECK(j["options"]["threads"] == 0);
  CHECK(j["backends"][0]["state"] == "reference");
  CHECK(j["backends"][1]["state"] == "incomplete");
  CHECK(j["backends"][1]["passed"] == 2);
  // The report shows a stopped check as such, and it is not a pass.
  const RunResult shown = test_rows_run({"report", "--out", dir.path("r"), "--check-json", file,
                                         "--no-accuracy", "--quick", "--backends", "ref-original"});
  INFO(shown.out << shown.err);
  CHECK(shown.exit_code == 1);
  CHECK(shown.out.find("the check was stopped before its end") != std::string::npos);
  CHECK(slurp(dir.path("r/report.md"))
            .find("Incomplete: a signal stopped this check after 2 of 8 cases") !=
        std::string::npos);
  // Resumed into another file: the stopped one is an input, left as it was.
  const std::string before = slurp(file);
  const RunResult done =
      test_rows_run({"check", "--resume", file, "--json", dir.path("done.json")});
  INFO(done.out << done.err);
  CHECK(done.exit_code == 0);
  CHECK(slurp(file) == before);
  CHECK(read_json(dir.path("done.json"))["complete"] == true);
  CHECK(read_json(dir.path("done.json"))["backends"][1]["passed"] == 8);
  CHECK(run_program("/bin/ls", {"-A", dir.path("")}).out == "ci.json\ndone.json\nr\n");
}

TEST_CASE("resume: what cannot be resumed is refused with one line, exit 2", "[resume]") {
  TempDir dir;
  const std::string file = dir.path("ci.json");
  const std::vector<std::string> run = {"check",   "--backends", "ref-original,ref-local",
                                        "--cases", "1000",       "--seed",
                                        "7",       "--json",     file};
  auto refused = [&](const std::vector<std::string>& args, const std::string& what) {
    const RunResult r = test_rows_run(args);
    INFO(r.out << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err_lines() == 1);
    CHECK(r.err.find(what) != std::string::npos);
  };
  REQUIRE(test_rows_run(run).exit_code == 0);
  refused({"check", "--resume", file}, "the check is complete (verdict passed): nothing to resume");
  REQUIRE(test_rows_run(run, 1).exit_code == 130);
  refused({"check", "--resume", file, "--seed", "8"}, "--seed given with --resume");
  refused({"check", "--resume", file, "--backends", "ref-original"},
          "--backends given with --resume");
  refused({"check", "--resume", dir.path("none.json")}, "none.json");
  const json stopped = read_json(file);
  auto tampered = [&](const char* name, auto change) {
    json j = stopped;
    change(j);
    std::ofstream(dir.path(name)) << j.dump();
    return dir.path(name);
  };
  refused({"check", "--resume",
           tampered("fp.json",
                    [](json& j) { j["campaign"]["corpus_fingerprint"] = "0000000000000000"; })},
          "corpus fingerprint 0000000000000000");
  refused({"check", "--resume",
           tampered("commit.json", [](json& j) { j["pxflow"]["commit"] = "abc"; })},
          "only the build that started a campaign finishes it");
  refused({"check", "--resume", tampered("key.json", [](json& j) { j.erase("campaign"); })},
          "campaign");
  std::ofstream(dir.path("text.json")) << "not json";
  refused({"check", "--resume", dir.path("text.json")}, "not valid JSON");
  // Another campaign's shards cannot merge a stopped one: it is finished first.
  refused({"merge", "--json", dir.path("m.json"), file},
          "finish it first with pxflow check --resume");
}

TEST_CASE("resume: a stopped report keeps its check in --out, the next one finishes it",
          "[resume]") {
  TempDir dir;
  const std::string out = dir.path("report");
  const std::vector<std::string> report = {
      "report", "--out",         out,      "--backends", "ref-original,ref-local", "--seed",
      "3",      "--no-accuracy", "--quick"};
  const RunResult stopped = test_rows_run(report, 3);
  INFO(stopped.out << stopped.err);
  REQUIRE(stopped.exit_code == 130);
  CHECK(stopped.err.find(out + "/check.json keeps the check (stopped)") != std::string::npos);
  const json kept = read_json(out + "/check.json");
  CHECK(kept["complete"] == false);
  CHECK(kept["cases"] == 3);
  CHECK(slurp(out + "/.pxflow-report") == "check.json\n");
  const RunResult rest = test_rows_run(report);
  INFO(rest.out << rest.err);
  CHECK(rest.exit_code == 0);
  CHECK(rest.out.find("(resuming " + out + "/check.json after 3 cases)") != std::string::npos);
  const json results = read_json(out + "/results.json");
  CHECK(results["check"]["complete"] == true);
  CHECK(results["check"]["cases"] == kept["cases_total"]);
  CHECK(slurp(out + "/check.json").empty());  // a complete report removes it
}
