// Nothing lost, nothing green that tested nothing (issue 15's first items), by running the
// binary: an output never overwrites an input, a lost write is an error (files and stdout), an
// output file is replaced only when complete, options that would have no effect are refused,
// and a check that compared nothing is not a pass.
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>

#include "bad_input.hpp"
#include "build_paths.hpp"
#include "results_files.hpp"
#include "run_program.hpp"
#include "sample_frames.hpp"

using namespace pxflow;
using test::kSampleNext;
using test::kSamplePrev;
using test::require_bad_input;
using test::run_pxflow;
using test::slurp;

TEST_CASE("an output path that is one of the inputs is refused before any work", "[cli][lost]") {
  test::TempDir dir;
  const std::string a = dir.path("a.png"), b = dir.path("b.png");
  dir.write("a.png", slurp(kSamplePrev));
  dir.write("b.png", slurp(kSampleNext));
  const std::string before = slurp(a);
  require_bad_input({"flow", "--draw", a, a, b}, "is an input");
  CHECK(slurp(a) == before);
  // The same file under another name (a hard link's inode) is the same input.
  REQUIRE(::link(a.c_str(), dir.path("same.png").c_str()) == 0);
  require_bad_input({"flow", "--draw", dir.path("same.png"), a, b}, "is an input");
  require_bad_input({"gap8", "--json", a, a, b}, "is an input");
}

TEST_CASE("a failed write is an error: stdout and files", "[cli][lost]") {
  const auto to_full =
      test::run_program("/bin/sh", {"-c", std::string(build_paths::pxflow) + " flow --json - " +
                                              kSamplePrev + " " + kSampleNext + " > /dev/full"});
  CHECK(to_full.exit_code == 1);
  CHECK(to_full.err.find("cannot write to standard output") != std::string::npos);
  const auto check = run_pxflow(
      {"check", "--backends", "ref-original,ref-local", "--generated-only", "--json", "/dev/full"});
  CHECK(check.exit_code == 1);
  CHECK(check.err.find("--json /dev/full: cannot write: No space left on device") !=
        std::string::npos);
}

TEST_CASE("a JSON file is replaced only when complete: a failed run leaves it intact",
          "[cli][lost]") {
  test::TempDir dir;
  const std::string json = dir.path("prev.json");
  dir.write("prev.json", "{\"previous\": true}\n");
  // Bad input after the path was accepted: the previous file stays as it was.
  require_bad_input({"check", "--backends", "ref-local", "--require", "ref-global", "--json", json},
                    "not among the backends");
  CHECK(slurp(json) == "{\"previous\": true}\n");
  // A good run replaces it whole, and leaves no temporary beside it.
  REQUIRE(run_pxflow(
              {"check", "--backends", "ref-original,ref-local", "--generated-only", "--json", json})
              .exit_code == 0);
  CHECK(slurp(json).find("\"backends\"") != std::string::npos);
  CHECK(run_pxflow({"check", "--help"}).exit_code == 0);
  const auto ls = test::run_program("/bin/ls", {dir.path("")});
  CHECK(ls.out == "prev.json\n");
}

TEST_CASE("a check that compared nothing but the reference is not a pass", "[cli][green]") {
  const auto r = run_pxflow({"check", "--backends", "ref-original", "--generated-only"});
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("nothing was checked") != std::string::npos);
  CHECK(r.out.find("ref-original   reference") != std::string::npos);
}

TEST_CASE("options that would have no effect are refused", "[cli][green]") {
  require_bad_input({"check", "--backends", "ref-local", "--require", "ref-global"},
                    "--require ref-global: not among the backends");
  require_bad_input({"flow", "--backend", "ref-local", "--device", "0", kSamplePrev, kSampleNext},
                    "no selected backend has devices");
  require_bad_input({"check", "--backends", "ref-original,ref-local", "--device", "1"},
                    "no selected backend has devices");
  require_bad_input({"flow", "--draw", "", kSamplePrev, kSampleNext}, "--draw needs a file name");
  require_bad_input({"flow", "--set", "gyro_comp=1", kSamplePrev, kSampleNext}, "gyro_comp=1");
  require_bad_input({"bench", "--batch", ""}, "--batch: needs at least one value");
  require_bad_input({"bench", "--set", "search_radius=6", "--radius", "2"},
                    "--radius and --set search_radius");
  require_bad_input({"check", "--seed", "-1"}, "--seed: must be a whole number");
  require_bad_input({"check", "--seed", "18446744073709551616"}, "--seed: must be a whole number");
}

TEST_CASE("report: wrong or malformed results files are refused before any work", "[cli][lost]") {
  test::TempDir dir;
  test::make_small_results(dir);
  dir.write("broken.json", "{\"backends\": [");
  dir.write("shape.json", "{\"backends\": [{\"name\": 1}], \"passed\": 0, \"failed\": 0}");
  const std::string out = dir.path("r");
  require_bad_input({"report", "--out", out, "--check-json", dir.path("b.json"), "--bench-json",
                     dir.path("b.json")},
                    "it is a bench file");
  require_bad_input({"report", "--out", out, "--check-json", dir.path("broken.json"),
                     "--bench-json", dir.path("b.json")},
                    "not valid JSON");
  require_bad_input({"report", "--out", out, "--check-json", dir.path("shape.json"), "--bench-json",
                     dir.path("b.json")},
                    "malformed check file");
  require_bad_input({"report", "--out", dir.path(""), "--check-json", dir.path("results.json")},
                    "results.json: no such file");
  CHECK(test::run_program("/bin/ls", {out}).exit_code != 0);  // nothing was made
}

TEST_CASE("report: a reused folder loses only the files the report wrote there", "[cli][lost]") {
  test::TempDir dir;
  test::make_small_results(dir);
  const std::string out = dir.path("r");
  REQUIRE(::mkdir(out.c_str(), 0755) == 0);
  dir.write("r/flow-old.png", "old picture");
  dir.write("r/mine.txt", "the user's");
  dir.write("escape.txt", "outside");
  dir.write("r/.pxflow-report", "flow-old.png\n../escape.txt\n/etc/hostname\n");
  // The user's results file inside the folder is an input: never overwritten.
  dir.write("r/results.json", slurp(dir.path("c.json")));
  require_bad_input({"report", "--out", out, "--check-json", dir.path("r/results.json"),
                     "--bench-json", dir.path("b.json")},
                    "is an input");
  ::unlink(dir.path("r/results.json").c_str());
  const auto r =
      run_pxflow({"report", "--out", out, "--check-json", dir.path("c.json"), "--bench-json",
                  dir.path("b.json"), "--no-accuracy", "--backends", "ref-original"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  // Listed by the old manifest, but not a name the report writes: kept (test_cli_output_plan).
  CHECK(slurp(dir.path("r/flow-old.png")) == "old picture");
  CHECK(slurp(dir.path("r/mine.txt")) == "the user's");
  CHECK(slurp(dir.path("escape.txt")) == "outside");
  CHECK(slurp(out + "/.pxflow-report") ==
        "report.md\nreport.html\nresults.json\nresults.csv\nconformance.csv\naccuracy.csv\n");
}

TEST_CASE("SIGINT and SIGTERM stop a run soon, exit 130 and 143, --json keeps what was done",
          "[cli][lost]") {
  for (const auto& [sig, code] : {std::pair{"INT", "130"}, std::pair{"TERM", "143"}}) {
    test::TempDir dir;
    const std::string json = dir.path("prev.json");
    dir.write("prev.json", "{\"previous\": true}\n");
    // A campaign far too long to finish, signalled once it runs: its first progress line comes
    // after the handlers are installed (a signal sent earlier to a background job of sh, which
    // starts with SIGINT ignored, would be lost). The shell reports the status and how long the
    // run took to stop after the signal, in ms.
    const std::string err = dir.path("err.txt");
    const std::string script =
        std::string("'") + build_paths::pxflow +
        "' check --backends ref-original,ref-local --cases 100000000 --progress --json '" + json +
        "' >/dev/null 2>'" + err + "' & p=$!; n=0; until grep -q 'pairs' '" + err +
        "' || [ $n -ge 600 ]; do sleep 0.1; n=$((n+1)); done; t0=$(date +%s%N); kill -" + sig +
        " $p; wait $p; rc=$?; echo rc=$rc ms=$(( ($(date +%s%N) - t0) / 1000000 )); cat '" + err +
        "' >&2";
    const auto r = test::run_program("/bin/sh", {"-c", script});
    INFO(r.out << r.err);
    REQUIRE(r.out.rfind(std::string("rc=") + code + " ms=", 0) == 0);
    const double ms = std::stod(r.out.substr(r.out.find("ms=") + 3));
    // It stopped: the campaign would run for days. How soon (the next batch) depends on the
    // machine's load, so the time is shown, never bounded (slow is not hung).
    INFO("stopped " << ms << " ms after the signal");
    CHECK(r.err.find(std::string("pxflow: interrupted: SIG") + sig + " after") !=
          std::string::npos);
    // The previous file is replaced whole by the cases checked (docs/harness.md, "Stopping and
    // resuming a campaign"), and no temporary is left.
    CHECK(slurp(json).find("\"complete\": false") != std::string::npos);
    CHECK(test::run_program("/bin/ls", {"-A", dir.path("")}).out == "err.txt\nprev.json\n");
  }
}

TEST_CASE("an interrupted run's stdout comes out before the interrupted line", "[cli][lost]") {
  // stdout and stderr into one file: stdout is then fully buffered, and the check's first line
  // ("pxflow check: seed ...") waits in the buffer when the signal comes.
  test::TempDir dir;
  const std::string both = dir.path("both.txt");
  const std::string script =
      std::string("'") + build_paths::pxflow +
      "' check --backends ref-original,ref-local --cases 100000000 --progress >'" + both +
      "' 2>&1 & p=$!; n=0; until grep -q 'pairs' '" + both +
      "' || [ $n -ge 600 ]; do sleep 0.1; n=$((n+1)); done; kill -INT $p; wait $p; echo rc=$?";
  const auto r = test::run_program("/bin/sh", {"-c", script});
  const std::string out = slurp(both);
  INFO(r.out << out);
  REQUIRE(r.out.rfind("rc=130", 0) == 0);
  const auto first = out.find("pxflow check: seed"), stop = out.find("pxflow: interrupted:");
  REQUIRE(first != std::string::npos);
  REQUIRE(stop != std::string::npos);
  CHECK(first < stop);
}

TEST_CASE("pxflow --version names the commit, the compiler and the families", "[cli]") {
  const auto r = run_pxflow({"--version"});
  CHECK(r.exit_code == 0);
  CHECK(r.out.rfind("pxflow 0.1 (commit ", 0) == 0);
  CHECK(r.out.find("backend families: reference") != std::string::npos);
}

TEST_CASE("progress goes to stderr when asked for, and only then off a terminal", "[cli]") {
  const std::vector<std::string> bench = {"bench", "--backends", "ref-local", "--batch",
                                          "1",     "--min-time", "0"};
  const auto quiet = run_pxflow(bench);
  CHECK(quiet.exit_code == 0);
  CHECK(quiet.err.empty());
  auto with = bench;
  with.push_back("--progress");
  const auto loud = run_pxflow(with);
  CHECK(loud.exit_code == 0);
  CHECK(loud.err.find("bench: process 1 of 5") != std::string::npos);
  with.insert(with.end(), {"--processes", "1"});
  const auto one = run_pxflow(with);
  CHECK(one.exit_code == 0);
  CHECK(one.err.find("bench: point 1 of 1") != std::string::npos);
}
