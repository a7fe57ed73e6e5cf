// Real signals to running checks and benches (docs/harness.md, "Stopping and resuming a
// campaign"): the work finished survives, marked incomplete, with no temporary file left, and a
// stopped check is finished by `check --resume`; an incomplete bench file is reported and
// compared with a note.
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

// Starts `pxflow ARGS` in the background (stdout to `out`, stderr to `err`), waits until `log`
// shows the extended regular expression `ready` (at most 60 s), sends SIGINT and prints "rc=N" with
// its exit status. The handlers are installed before the first line, so the signal is never lost to
// a job started with SIGINT ignored.
RunResult interrupted_when(const std::string& args, const std::string& out, const std::string& err,
                           const std::string& log, const std::string& ready) {
  const std::string script =
      std::string("'") + build_paths::pxflow_with_test_rows + "' " + args + " >'" + out + "' 2>'" +
      err + "' & p=$!; n=0; until grep -qE -e '" + ready + "' '" + log +
      "' || [ $n -ge 600 ]; do sleep 0.1; n=$((n+1)); done; kill " + "-INT $p; wait $p; echo rc=$?";
  return run_program("/bin/sh", {"-c", script});
}

// A fuzz campaign long enough for a signal to land in its middle, sized for the build: under the
// sanitizers a pair costs about five times as much (docs/test-suite.md, "The test suite's time"),
// so a fifth of the pairs runs about as long. A fuzz case is a batch of 256 pairs.
#ifdef __SANITIZE_ADDRESS__
constexpr long kLongCampaignPairs = 4000;
#else
constexpr long kLongCampaignPairs = 20000;
#endif
constexpr long kLongCampaignCases = (kLongCampaignPairs + 255) / 256;

}  // namespace

TEST_CASE("resume: SIGINT to a running check --json keeps what it checked, --resume finishes it",
          "[resume][signal]") {
  TempDir dir;
  const std::string json_path = dir.path("ci.json"), err = dir.path("err.txt");
  // Signalled once its live line (a few a second) counts the second case or a later one: at
  // least one is done of the campaign's cases.
  const RunResult r = interrupted_when("check --backends ref-original,ref-local --cases " +
                                           std::to_string(kLongCampaignPairs) +
                                           " --progress --json '" + json_path + "'",
                                       "/dev/null", err, err, "check: ([2-9]|[0-9]{2}) of");
  INFO(r.out << slurp(err));
  REQUIRE(r.out.rfind("rc=130", 0) == 0);
  CHECK(slurp(err).find("pxflow: interrupted: SIGINT after ") != std::string::npos);
  const json stopped = read_json(json_path);
  CHECK(stopped["complete"] == false);
  CHECK(stopped["verdict"] == "incomplete");
  CHECK(stopped["cases"].get<long>() > 0);
  CHECK(stopped["cases_total"] == kLongCampaignCases);
  CHECK(run_program("/bin/ls", {"-A", dir.path("")}).out == "ci.json\nerr.txt\n");

  const RunResult done =
      run_program(build_paths::pxflow_with_test_rows, {"check", "--resume", json_path});
  INFO(done.out << done.err);
  CHECK(done.exit_code == 0);
  const json complete = read_json(json_path);
  CHECK(complete["complete"] == true);
  CHECK(complete["verdict"] == "passed");
  CHECK(complete["cases"] == kLongCampaignCases);
  CHECK(complete["pairs"] == kLongCampaignPairs);
  CHECK(complete["backends"][1]["passed"] == kLongCampaignCases);
  CHECK(run_program("/bin/ls", {"-A", dir.path("")}).out == "ci.json\nerr.txt\n");
}

TEST_CASE("resume: SIGINT to a running bench --json keeps its rows, report and compare say so",
          "[resume][signal]") {
  TempDir dir;
  const std::string bench = dir.path("b.json"), out = dir.path("out.txt");
  // Signalled once the second point begins: the first is measured whole (one process, whose
  // table shows the points as they come; file_matrix stops bench --processes R too).
  const RunResult r = interrupted_when(
      "bench --backends ref-original,ref-local --batch 1,4,16,64 --processes 1 "
      "--min-time 0.3 --json '" +
          bench + "'",
      out, dir.path("err.txt"), out, "batch=4 threads");
  INFO(r.out << slurp(out) << slurp(dir.path("err.txt")));
  REQUIRE(r.out.rfind("rc=130", 0) == 0);
  const json b = read_json(bench);
  CHECK(b["complete"] == false);
  CHECK(b["points_total"] == 4);
  CHECK(b["points_done"].get<long>() >= 1);
  CHECK(b["rows"].size() >= 2);
  CHECK(slurp(dir.path("err.txt")).find("b.json holds its rows") != std::string::npos);
  CHECK(run_program("/bin/ls", {"-A", dir.path("")}).out == "b.json\nerr.txt\nout.txt\n");

  const std::string check = dir.path("c.json");
  REQUIRE(run_program(
              build_paths::pxflow_with_test_rows,
              {"check", "--backends", "ref-original,ref-local", "--cases", "300", "--json", check})
              .exit_code == 0);
  const RunResult report = run_program(build_paths::pxflow_with_test_rows,
                                       {"report", "--out", dir.path("r"), "--check-json", check,
                                        "--bench-json", bench, "--no-accuracy"});
  INFO(report.out << report.err);
  CHECK(report.exit_code == 0);
  CHECK(slurp(dir.path("r/report.md")).find("Incomplete: a signal stopped this bench after") !=
        std::string::npos);
  const RunResult compare =
      run_program(build_paths::pxflow_with_test_rows, {"compare", bench, bench});
  INFO(compare.out << compare.err);
  CHECK(compare.exit_code == 0);
  CHECK(compare.out.find("warning: A is incomplete: a signal stopped its bench after") !=
        std::string::npos);
}
