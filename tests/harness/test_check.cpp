// pxflow check against backends that are wrong on purpose: the mismatch line, the counts, the
// exit code, skips, --require, n/a cases, fuzz campaigns and the JSON file.
#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "build_paths.hpp"
#include "run_program.hpp"

using pxflow::test::last_line;
using pxflow::test::run_program;

namespace {

pxflow::test::RunResult check(std::vector<std::string> args) {
  args.insert(args.begin(), "check");
  return run_program(build_paths::pxflow_with_test_rows, args);
}

}  // namespace

TEST_CASE("a backend that flips one bit fails with one line naming the field", "[check]") {
  const auto r = check({"--backends", "test-bitflip", "--generated-only", "--no-repro"});
  INFO(r.out);
  CHECK(r.exit_code == 1);
  // poi 3 of the first random px4flow-64 pair; sub[2] only differs when the POI was accepted,
  // so look for the field rather than a fixed pair.
  CHECK(r.out.find("FAIL test-bitflip case=") != std::string::npos);
  CHECK(r.out.find("poi=3 (x=23,y=5) field=sub[2]") != std::string::npos);
  CHECK(r.out.find("pair=") != std::string::npos);
  CHECK(r.out.find("seed=") != std::string::npos);
  // Every generated case fails (some limit cases, FT = 65535 say, accept no POI: nothing to flip).
  CHECK(r.out.find("test-bitflip   failed") != std::string::npos);
  CHECK(last_line(r.out).find(" failed, 0 skipped") != std::string::npos);
}

TEST_CASE("an unwritten record is caught by the sentinel", "[check]") {
  const auto r = check({"--backends", "test-unwritten", "--generated-only", "--no-repro"});
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("poi=5 (x=35,y=5) field=record expected=written got=never written") !=
        std::string::npos);
}

TEST_CASE("correct backends pass: the summary line counts cases", "[check]") {
  const auto r = check({"--backends", "ref-local,ref-global", "--generated-only"});
  INFO(r.out);
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("FAIL") == std::string::npos);
  // 4 settings x 4 generated cases and each row's 49 limit cases (check_limits.hpp: SPEC's
  // corners, its strips and its radius sweep S = 1..31), 2 backends
  CHECK(last_line(r.out) == "130 passed, 0 failed, 0 skipped");
}

TEST_CASE("a backend that cannot run is skipped with its reason, or fails when required",
          "[check]") {
  auto r = check({"--backends", "test-unavailable,ref-local", "--generated-only"});
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("skip test-unavailable (no such device here (test row))") != std::string::npos);
  CHECK(last_line(r.out) == "65 passed, 0 failed, 65 skipped");
  r = check({"--backends", "test-unavailable,ref-local", "--require", "test-unavailable",
             "--generated-only"});
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("FAIL test-unavailable: required but cannot run") != std::string::npos);
  r = check({"--backends", "test-unavailable", "--require", "all", "--generated-only"});
  CHECK(r.exit_code == 1);
}

TEST_CASE("a row whose hardware this machine lacks: --require all skips it, --require NAME fails",
          "[check]") {
  auto r =
      check({"--backends", "test-no-hardware,ref-local", "--require", "all", "--generated-only"});
  INFO(r.out);
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("skip test-no-hardware (this CPU lacks it (test row))") != std::string::npos);
  r = check({"--backends", "test-no-hardware,ref-local", "--require", "test-no-hardware",
             "--generated-only"});
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("FAIL test-no-hardware: required but cannot run") != std::string::npos);
}

TEST_CASE("cases outside a backend's limits are n/a, not failures", "[check]") {
  const auto r = check({"--backends", "test-small-only", "--generated-only"});
  INFO(r.out);
  CHECK(r.exit_code == 0);
  // The 8 generated cases at 64x64 and the 43 limit cases within 64x64: SPEC's corners that fit
  // and its own edges (the largest square it accepts, 64x64, the strips 64x19 and 19x64, the
  // largest radius, and the radius sweep S = 1..26 on frames of at most 4096 pixels).
  CHECK(last_line(r.out) == "51 passed, 0 failed, 0 skipped");
  CHECK(r.out.find(" 1126    11 ") != std::string::npos);  // pairs, then the n/a column
  CHECK(r.out.find("test-small-only: 43, its own: ") != std::string::npos);
  for (const char* own : {"largest-square 64x64 S=4 B=8", "widest 64x19 S=4 B=8",
                          "tallest 19x64 S=4 B=8", "largest-radius 63x63 S=26 B=1"})
    CHECK(r.out.find(own) != std::string::npos);
  // The check file lists them per backend; --limits-only runs them alone.
  pxflow::test::TempDir dir;
  const auto only =
      check({"--backends", "test-small-only", "--limits-only", "--json", dir.path("l.json")});
  CHECK(only.exit_code == 0);
  CHECK(last_line(only.out) == "43 passed, 0 failed, 0 skipped");
  std::ifstream in(dir.path("l.json"));
  const auto j = nlohmann::json::parse(in);
  const auto limits = j["backends"][0]["limits"].get<std::vector<std::string>>();
  CHECK(limits.size() == 43);
  CHECK(std::find(limits.begin(), limits.end(),
                  "limits/largest-square of test-small-only 64x64 S=4 B=8") != limits.end());
  CHECK(r.out.find("radius-sweep S=1..26") != std::string::npos);
  // The same cases, pair for pair, with other rows selected: a row's corpus is its own.
  const auto with_others =
      check({"--backends", "test-small-only,ref-local,test-crash", "--limits-only", "--json",
             dir.path("others.json"), "--case-timeout", "5"});
  std::ifstream in2(dir.path("others.json"));
  const auto j2 = nlohmann::json::parse(in2);
  REQUIRE(j2["backends"][0]["backend"] == "test-small-only");
  CHECK(j2["backends"][0]["limits"] == j["backends"][0]["limits"]);
  CHECK(j2["backends"][0]["pairs"] == j["backends"][0]["pairs"]);
  CHECK(j2["backends"][0]["not_applicable"] == j["backends"][0]["not_applicable"]);
  const auto fuzz = check({"--limits-only", "--cases", "5"});
  CHECK(fuzz.exit_code == 2);
  CHECK(fuzz.err.find("--limits-only: the limit cases are part of the fixed corpus") !=
        std::string::npos);
}

TEST_CASE("check --set and --profile run the corpus at other parameters, each case at its size",
          "[check]") {
  pxflow::test::TempDir dir;
  const auto r = check({"--backends", "ref-local", "--generated-only", "--set", "search_radius=20",
                        "--json", dir.path("s20.json")});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  std::ifstream in(dir.path("s20.json"));
  const auto j = nlohmann::json::parse(in);
  CHECK(j["options"]["sets"] == nlohmann::json::array({"search_radius=20"}));
  CHECK(j["command"].get<std::string>().find(" --set search_radius=20") != std::string::npos);
  // Every generated setting ran at S = 20; the limit cases kept their own parameters.
  const auto settings = j["campaign"]["settings"].get<std::vector<std::string>>();
  for (const char* s : {"px4flow-64 --set search_radius=20", "px4flow-head --set search_radius=20",
                        "320x240 S=7 B=16 --set search_radius=20",
                        "640x480 S=6 B=32 HF off --set search_radius=20"})
    CHECK(std::find(settings.begin(), settings.end(), s) != settings.end());
  CHECK(std::find(settings.begin(), settings.end(), "px4flow-64") == settings.end());
  // A radius too large for the 64x64 frames leaves those settings out, each named.
  const auto big = check({"--backends", "ref-local", "--generated-only", "--set",
                          "search_radius=31", "--profile", "px4flow-head"});
  CHECK(big.exit_code == 0);
  CHECK(big.out.find("left out at --profile px4flow-head --set search_radius=31: px4flow-64: "
                     "frame 64x64 is too small for search_radius 31") != std::string::npos);
  // What no case could run at is bad input, one line.
  for (const auto& bad : {std::vector<std::string>{"--set", "width=80"},
                          {"--set", "search_radius=40"},
                          {"--profile", "nope"},
                          {"--set", "search_radius=8", "--limits-only"}}) {
    auto args = bad;
    args.insert(args.begin(), {"--backends", "ref-local", "--generated-only"});
    const auto e = check(args);
    CHECK(e.exit_code == 2);
    CHECK(e.err_lines() == 1);
  }
}

TEST_CASE("a backend that crashes or hangs is its row's failure line, the others are checked",
          "[check]") {
  const auto r = check(
      {"--backends", "test-crash,test-hang,ref-local", "--cases", "1", "--case-timeout", "2"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("FAIL test-crash case=fuzz[px4flow-64] killed by SIGSEGV in case 0 'fuzz' "
                   "pair 0 'random/") != std::string::npos);
  CHECK(r.out.find("FAIL test-hang case=fuzz[px4flow-64] did not finish case 0 'fuzz' within "
                   "2 s (--case-timeout)\n") != std::string::npos);
  CHECK(r.out.find("\nref-local      passed ") != std::string::npos);
  CHECK(last_line(r.out) == "1 passed, 2 failed, 0 skipped");
}

TEST_CASE("Ctrl-C stops a check waiting on a worker: exit 130, nothing failed", "[check]") {
  pxflow::test::TempDir dir;
  const pid_t pid = pxflow::test::start_program(
      build_paths::pxflow_with_test_rows,
      {"check", "--backends", "test-hang", "--cases", "1", "--progress"}, dir.path("out"),
      dir.path("err"));
  // The progress line (stderr, unbuffered) comes once the workers have opened their backends and
  // the case is sent: then the check waits on the hanging worker.
  std::string progress;
  for (int i = 0; i < 600 && progress.find("check: 1 of") == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::ifstream in(dir.path("err"));
    progress.assign(std::istreambuf_iterator<char>(in), {});
  }
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  std::ifstream in(dir.path("err")), out_file(dir.path("out"));
  const std::string err(std::istreambuf_iterator<char>(in), {});
  const std::string out(std::istreambuf_iterator<char>(out_file), {});
  INFO(out << err);
  CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 130));
  CHECK(err.find("pxflow: interrupted: SIGINT") != std::string::npos);
  CHECK(out.find("FAIL") == std::string::npos);
}

TEST_CASE("fuzz campaign, JSON file, and bad arguments", "[check]") {
  pxflow::test::TempDir dir;
  const auto r = check(
      {"--backends", "ref-local", "--cases", "600", "--seed", "7", "--json", dir.path("c.json")});
  INFO(r.out);
  CHECK(r.exit_code == 0);
  CHECK(last_line(r.out) == "3 passed, 0 failed, 0 skipped");  // 256 + 256 + 88 pairs
  std::ifstream in(dir.path("c.json"));
  const auto j = nlohmann::json::parse(in);
  CHECK(j["seed"] == 7);
  CHECK(j["pairs"] == 600);
  CHECK(j["backends"][0]["backend"] == "ref-local");
  CHECK(j["backends"][0]["state"] == "passed");

  const auto bad = check({"--backends", "no-such-backend"});
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("unknown backend 'no-such-backend'") != std::string::npos);
  CHECK(bad.err_lines() == 1);
  CHECK(check({"--cases", "0"}).exit_code == 2);
}

TEST_CASE("bench times only checked backends and writes the documented JSON rows", "[bench]") {
  pxflow::test::TempDir dir;
  const auto r =
      run_program(build_paths::pxflow_with_test_rows,
                  {"bench", "--backends", "ref-original,ref-local,test-bitflip,test-unavailable",
                   "--batch", "1,3", "--min-time", "0", "--json", dir.path("b.json")});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 1);  // a row's records differ: the others are timed, the bench fails
  CHECK(r.out.find("not timed: records differ from ref-original") != std::string::npos);
  CHECK(r.out.find("\ntest-bitflip ") != std::string::npos);  // a row of the one table
  CHECK(r.out.find("skipped test-unavailable: no such device here") != std::string::npos);
  std::ifstream in(dir.path("b.json"));
  const auto j = nlohmann::json::parse(in);
  int timed = 0;
  for (const auto& row : j["rows"]) {
    for (const char* key : {"backend", "profile", "width", "height", "batch", "threads", "source"})
      REQUIRE(row.contains(key));
    if (row["backend"] == "test-bitflip") {
      CHECK(row["median_ns_per_frame"] == 0);
      continue;
    }
    ++timed;
    CHECK(row["median_ns_per_frame"].get<double>() > 0);
    CHECK(row["frames_per_s"].get<double>() > 0);
    CHECK(row["width"] == 64);
    if (row["backend"] == "ref-original") CHECK(row["speedup_vs_ref_original"] == 1.0);
  }
  CHECK(timed == 4);  // 2 backends x 2 batch sizes
#if defined(__x86_64__) && defined(PXFLOW_TEST_EXPECT_BOUND)
  // x86-64: the cpu family's SAD-instruction bound is measured, and every TSC row carries its
  // distance.
  REQUIRE(j.contains("bound"));
  CHECK(j["bound"]["clock"] == "tsc");
  CHECK(j["bound"]["bytes_per_cycle"].get<double>() > 0);
  for (const auto& row : j["rows"])
    if (row.contains("cycles_per_frame")) CHECK(row["bound_ratio"].get<double>() > 0);
#endif
  CHECK(run_program(build_paths::pxflow_with_test_rows, {"bench", "--batch", "0"}).exit_code == 2);
  CHECK(run_program(build_paths::pxflow_with_test_rows, {"bench", "--sizes", "8x8"}).exit_code ==
        2);
}

TEST_CASE("counts are checked: a backend that miscounts fails with one line naming both",
          "[check]") {
  const auto r = check({"--backends", "test-miscount,test-small-only", "--generated-only"});
  INFO(r.out);
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("field=") == std::string::npos);  // its records are right
  // Its counts are 512 SAD ops above ref-original's counting model, in every case.
  const std::string needle = "counts differ from ref-original's: sad_ops ";
  const auto at = r.out.find("FAIL test-miscount case=");
  REQUIRE(at != std::string::npos);
  const auto line_end = r.out.find('\n', at);
  const std::string line = r.out.substr(at, line_end - at);
  const auto n = line.find(needle);
  REQUIRE(n != std::string::npos);
  auto number = [](std::string s) {
    s.erase(std::remove(s.begin(), s.end(), ','), s.end());
    return std::stol(s);
  };
  std::istringstream words(line.substr(n + needle.size()));
  std::string got, vs, want;
  words >> got >> vs >> want;
  CHECK(vs == "vs");
  CHECK(number(got) == number(want) + 512);
  // test-small-only, ref-original's kernel, counts right: its 51 cases within 64x64 pass (8
  // generated, 43 limit cases); test-miscount fails every case it runs (16 and its 49).
  CHECK(r.out.find("FAIL test-small-only") == std::string::npos);
  CHECK(last_line(r.out) == "51 passed, 65 failed, 0 skipped");
}

namespace {

// The command after `marker` on its line, split at spaces, "pxflow" replaced by the test binary.
// The command printed after `marker`, as it would be pasted into a shell.
std::string printed_command(const std::string& out, const std::string& marker) {
  const auto at = out.find(marker);
  if (at == std::string::npos) return {};
  const auto from = at + marker.size();
  return out.substr(from, out.find('\n', from) - from);
}

// The printed command run by a shell whose PATH is empty: it must name pxflow by its path.
pxflow::test::RunResult paste_without_path(const std::string& command) {
  return run_program("/bin/sh", {"-c", "PATH=; export PATH; " + command});
}

}  // namespace

TEST_CASE("a planted half-pixel bug: the stage in words and a reproducer that shows it",
          "[check]") {
  pxflow::test::TempDir dir;
  const auto r =
      check({"--backends", "test-half-step-swap", "--generated-only", "--repro-dir", dir.path("")});
  INFO(r.out);
  CHECK(r.exit_code == 1);
  CHECK(r.out.find(" first differing stage: half-pixel refinement: sub[0] (half step (1,0))") !=
        std::string::npos);
  const std::string folder = dir.path("pxflow-repro-1/test-half-step-swap");
  CHECK(r.out.find("reproducer in " + folder) != std::string::npos);
  // One pair of 2S+11 pixels a side (S = 4 in the first failing case): one POI.
  CHECK(std::filesystem::file_size(folder + "/prev.raw") == 19 * 19);
  CHECK(std::filesystem::file_size(folder + "/next.raw") == 19 * 19);
  const auto mine = printed_command(r.out, " reproducer shows it: ");
  const auto theirs = printed_command(r.out, " reproducer against: ");
  REQUIRE(!mine.empty());
  REQUIRE(!theirs.empty());
  // The commands name the binary that ran, by its absolute path: they run with no PATH at all.
  CHECK(
      mine.rfind(std::filesystem::canonical(build_paths::pxflow_with_test_rows).string() + " flow ",
                 0) == 0);
  const auto a = paste_without_path(mine);
  const auto b = paste_without_path(theirs);
  INFO(a.err << b.err);
  REQUIRE(a.exit_code == 0);
  REQUIRE(b.exit_code == 0);
  const auto pois_a = nlohmann::json::parse(a.out)["pois"];
  const auto pois_b = nlohmann::json::parse(b.out)["pois"];
  CHECK(pois_a.size() == 1);
  CHECK(pois_a != pois_b);  // the difference, on one small pair
  CHECK(pois_a[0]["sub"] != pois_b[0]["sub"]);

  // A second run never replaces the first one's folder.
  const auto again =
      check({"--backends", "test-half-step-swap", "--generated-only", "--repro-dir", dir.path("")});
  CHECK(again.out.find("reproducer in " + dir.path("pxflow-repro-2/")) != std::string::npos);
  // --no-repro: the stage is still named, no folder is made.
  const auto off = check({"--backends", "test-half-step-swap", "--generated-only", "--no-repro",
                          "--repro-dir", dir.path("")});
  CHECK(off.out.find("first differing stage: half-pixel refinement") != std::string::npos);
  CHECK(!std::filesystem::exists(dir.path("pxflow-repro-3")));
  // A --repro-dir that does not exist is bad input, before any work.
  const auto missing =
      check({"--backends", "ref-local", "--generated-only", "--repro-dir", dir.path("missing")});
  CHECK(missing.exit_code == 2);
  CHECK(missing.err_lines() == 1);
}
