// One output plan and one interrupt policy for every command (issue 23, items 1 and 2), by
// running the binary: every path a command writes is checked before any work against every file
// it reads and against each other, and created first; a report never touches a folder of the
// user's; Ctrl-C stops every command; a sequence that stops early keeps its completed pairs.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>

#include "bad_input.hpp"
#include "build_paths.hpp"
#include "results_files.hpp"
#include "run_program.hpp"
#include "sample_frames.hpp"

using namespace pxflow;
using pxflow::test::kData;
using test::require_bad_input;
using test::run_pxflow;
using test::slurp;

namespace {

std::string quoted(const std::vector<std::string>& args) {
  // Not "'" + std::string(...): GCC 12 warns on that one (-Wrestrict, a false positive, GCC
  // bug 105329).
  std::string s = std::string("'") + build_paths::pxflow + "'";
  for (const std::string& a : args) s += " '" + a + "'";
  return s;
}

// Runs pxflow in the background and, once its signal handlers are in place (the process is
// pxflow, not yet the shell that starts it, and SigCgt in /proc/PID/status has SIGINT), stops it,
// sends `sig` and lets it go on: the signal is pending before the run can finish, however fast the
// machine. Returns the shell's "rc=N" line and pxflow's stderr.
test::RunResult interrupt_once_started(const std::vector<std::string>& args, const char* sig,
                                       const std::string& err_file) {
  const std::string script =
      quoted(args) + " >/dev/null 2>'" + err_file +
      "' & p=$!; n=0; until { [ \"$(readlink /proc/$p/exe)\" = '" + build_paths::pxflow +
      "' ] && [ $(( 0x$(awk '/^SigCgt/{print $2}' /proc/$p/status) & 2 )) -ne 0 ]; } "
      "|| [ $n -ge 3000 ]; do sleep 0.01; n=$((n+1)); done; kill -STOP $p; kill -" +
      sig + " $p; kill -CONT $p; wait $p; echo rc=$?; cat '" + err_file + "' >&2";
  return test::run_program("/bin/sh", {"-c", script});
}

std::size_t lines_in(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace

TEST_CASE("check refuses a --json that is a frame it reads, before any work", "[cli][plan]") {
  // A copy of the real frames' folder (never the opencv-doc folder itself: a broken refusal
  // would write into it).
  test::TempDir dir;
  REQUIRE(::mkdir(dir.path("data").c_str(), 0755) == 0);
  const std::string frame = dir.path("data/rubberwhale1.png");
  dir.write("data/rubberwhale1.png", slurp(kData + "/rubberwhale1.png"));
  const std::string before = slurp(frame);
  require_bad_input({"check", "--data", dir.path("data"), "--json", frame}, "the folder --data");
  require_bad_input({"check", "--data", dir.path("data"), "--json", dir.path("data/new.json")},
                    "pxflow never writes where it reads");
  CHECK(slurp(frame) == before);
  CHECK(test::run_program("/bin/ls", {"-A", dir.path("data")}).out == "rubberwhale1.png\n");
  // A folder named as --data is never written into, even by a run that reads none of it
  // (--generated-only): an input option's value is an input, whatever the command then reads.
  require_bad_input({"check", "--backends", "ref-original,ref-local", "--generated-only", "--data",
                     dir.path("data"), "--json", dir.path("data/c.json")},
                    "pxflow never writes where it reads");
}

TEST_CASE("two outputs that are one file are refused, whatever their spelling", "[cli][plan]") {
  test::TempDir dir;
  const std::string a = dir.path("a.raw"), b = dir.path("b.raw");
  dir.write("a.raw", std::string(64 * 64, '\x40'));
  dir.write("b.raw", std::string(64 * 64, '\x41'));
  require_bad_input(
      {"flow", "--size", "64x64", "--jsonl", dir.path("o.x"), "--csv", dir.path("o.x"), a, b},
      "the same file");
  require_bad_input(
      {"flow", "--size", "64x64", "--jsonl", dir.path("o.x"), "--csv", dir.path("./o.x"), a, b},
      "the same file");
  require_bad_input(
      {"flow", "--size", "64x64", "--json", dir.path("o.png"), "--draw", dir.path("o.png"), a, b},
      "the same file");
  require_bad_input({"flow", "--size", "64x64", "--jsonl", "-", "--csv", "-", a, b},
                    "only one of them can write to standard output");
  // A sequence's streams too.
  dir.write("list.txt", "a.raw b.raw\n");
  require_bad_input({"flow", "--size", "64x64", "--jsonl", dir.path("s"), "--csv", dir.path("s"),
                     "--pairs", dir.path("list.txt")},
                    "the same file");
  CHECK(test::run_program("/bin/ls", {"-A", dir.path("")}).out == "a.raw\nb.raw\nlist.txt\n");
}

TEST_CASE("an output that cannot be created is refused before any work", "[cli][plan]") {
  // procfs refuses new files even to root (a read-only folder would not stop root).
  const std::string out = "/proc/pxflow-plan-test.json";
  require_bad_input(
      {"check", "--backends", "ref-original,ref-local", "--generated-only", "--json", out},
      "cannot be created");
  require_bad_input({"bench", "--backends", "ref-original", "--json", out}, "cannot be created");
  require_bad_input({"gap8", "--json", out}, "cannot be created");
  require_bad_input({"backends", "--json", out}, "cannot be created");
  require_bad_input({"flow", "--jsonl", out, kData + "/vtest.avi"}, "cannot be created");
  require_bad_input({"flow", "--draw", "/proc", kData + "/vtest.avi"}, "cannot create files in it");
  require_bad_input({"report", "--out", "/proc/pxflow-report", "--no-accuracy"},
                    "cannot create the folder");
}

TEST_CASE("report --out never touches a folder of the user's", "[cli][plan]") {
  test::TempDir dir;
  test::make_small_results(dir);
  REQUIRE(::mkdir(dir.path("mine").c_str(), 0755) == 0);
  dir.write("mine/report.md", "my notes");
  dir.write("mine/results.csv", "my,data\n");
  require_bad_input({"report", "--out", dir.path("mine"), "--check-json", dir.path("c.json"),
                     "--bench-json", dir.path("b.json"), "--no-accuracy"},
                    "no earlier pxflow output (.pxflow-report)");
  CHECK(slurp(dir.path("mine/report.md")) == "my notes");
  CHECK(slurp(dir.path("mine/results.csv")) == "my,data\n");
  CHECK(test::run_program("/bin/ls", {"-A", dir.path("mine")}).out == "report.md\nresults.csv\n");
}

TEST_CASE("a report's manifest can only remove files the report writes", "[cli][plan]") {
  test::TempDir dir;
  test::make_small_results(dir);
  REQUIRE(::mkdir(dir.path("r").c_str(), 0755) == 0);
  dir.write("r/mydata.txt", "the user's");
  dir.write("r/flow-vtest.avi.png", "a picture of an earlier run");
  dir.write("r/.pxflow-report", "mydata.txt\nflow-vtest.avi.png\nreport.md\n");
  const auto r = run_pxflow({"report", "--out", dir.path("r"), "--check-json", dir.path("c.json"),
                             "--bench-json", dir.path("b.json"), "--no-accuracy", "--backends",
                             "ref-original"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(slurp(dir.path("r/mydata.txt")) == "the user's");
  CHECK(test::run_program("/bin/ls", {dir.path("r/flow-vtest.avi.png")}).exit_code != 0);
}

TEST_CASE("Ctrl-C stops accuracy, vectors and gap8 with exit 130", "[cli][plan]") {
  test::TempDir dir;
  const std::vector<std::vector<std::string>> runs = {
      {"accuracy", "--cases", "2000"},
      {"vectors", "--cases", "2000", "--out", dir.path("vec")},
      {"gap8", "--variant", "all", "--cores", "1-8", "--json", dir.path("g.json")}};
  for (const auto& args : runs) {
    const auto r = interrupt_once_started(args, "INT", dir.path("err.txt"));
    INFO(args[0] << ": " << r.out << r.err);
    CHECK(r.out.rfind("rc=130", 0) == 0);
    CHECK(r.err.find("pxflow: interrupted: SIGINT after") != std::string::npos);
    CHECK(r.err.find("no output file was changed") != std::string::npos);
  }
  CHECK(test::run_program("/bin/ls", {"-A", dir.path("vec")}).out.empty());
  CHECK(test::run_program("/bin/ls", {dir.path("g.json")}).exit_code != 0);
}

TEST_CASE("a sequence that stops early keeps every completed pair and says so", "[cli][plan]") {
  test::TempDir dir;
  dir.write("out.jsonl", "previous\n");
  SECTION("interrupted after N pairs: N lines and the marker, exit 130") {
    const auto r = interrupt_once_started(
        {"flow", "--jsonl", dir.path("out.jsonl"), "--csv", dir.path("out.csv"), "--set",
         "search_radius=20", kData + "/vtest.avi"},
        "INT", dir.path("err.txt"));
    INFO(r.out << r.err);
    REQUIRE(r.out.rfind("rc=130", 0) == 0);
    const auto at = r.err.find("flow: incomplete: ");
    if (at == std::string::npos) {
      // Stopped before its first pair: nothing to keep, the previous file stays.
      CHECK(r.err.find("after 0 pairs done; no output file was changed") != std::string::npos);
      CHECK(slurp(dir.path("out.jsonl")) == "previous\n");
    } else {
      const std::size_t n = std::stoul(r.err.substr(at + 18));
      const std::string jsonl = slurp(dir.path("out.jsonl")), csv = slurp(dir.path("out.csv"));
      CHECK(lines_in(jsonl) == n + 1);  // and the incomplete marker
      CHECK(jsonl.ends_with("{\"incomplete\": {\"records\": " + std::to_string(n) +
                            ", \"stopped_by\": \"SIGINT\"}}\n"));
      CHECK(lines_in(csv) == n + 2);  // the header and the marker
      CHECK(
          csv.ends_with("\n# incomplete: " + std::to_string(n) + " records, stopped by SIGINT\n"));
      CHECK(r.err.find(" pairs done before the stop; kept " + std::to_string(n) +
                       " pairs in --jsonl " + dir.path("out.jsonl") +
                       " (marked incomplete), --csv " + dir.path("out.csv") +
                       " (marked incomplete)") != std::string::npos);
    }
  }
  SECTION("a bad frame after three good ones: two pairs kept and marked, exit 2") {
    REQUIRE(::mkdir(dir.path("seq").c_str(), 0755) == 0);
    for (const char* f : {"seq/f1.raw", "seq/f2.raw", "seq/f3.raw"})
      dir.write(f, std::string(64 * 64, '\x40'));
    dir.write("seq/f4.raw", "too short");
    const auto r =
        run_pxflow({"flow", "--size", "64x64", "--jsonl", dir.path("out.jsonl"), dir.path("seq")});
    INFO(r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("flow: incomplete: 2 pairs done before the stop; kept 2 pairs in --jsonl") !=
          std::string::npos);
    const std::string jsonl = slurp(dir.path("out.jsonl"));
    CHECK(lines_in(jsonl) == 3);
    CHECK(jsonl.ends_with("{\"incomplete\": {\"records\": 2, \"stopped_by\": \"bad input\"}}\n"));
  }
  SECTION("Ctrl-C on a pipe: the writer dies too, and the run is still incomplete") {
    // Ctrl-C reaches the whole pipeline: the writer dies and pxflow sees the end of its input;
    // it must still say incomplete and exit 130, never 0. Once two pairs are in the stream's
    // file, pxflow gets SIGINT and then the writer is killed, as a terminal would do both.
    const std::string fifo = dir.path("frames.fifo"), err = dir.path("err.txt");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const std::string script =
        "(head -c 12288 /dev/zero; exec sleep 600) >'" + fifo + "' & w=$!; " +
        quoted({"flow", "--size", "64x64", "--jsonl", dir.path("out.jsonl"), "-"}) + " <'" + fifo +
        "' >/dev/null 2>'" + err + "' & p=$!; n=0; until [ \"$(cat '" + dir.path("") +
        "'.out.jsonl.pxflow-*.tmp 2>/dev/null | wc -l)\" -ge 2 ] || [ $n -ge 3000 ]; do sleep "
        "0.01; "
        "n=$((n+1)); done; kill -INT $p; kill $w; wait $p; echo rc=$?; cat '" +
        err + "' >&2";
    const auto r = test::run_program("/bin/sh", {"-c", script});
    INFO(r.out << r.err);
    CHECK(r.out.rfind("rc=130", 0) == 0);
    CHECK(r.err.find("flow: incomplete: 2 pairs done before the stop") != std::string::npos);
    CHECK(lines_in(slurp(dir.path("out.jsonl"))) == 3);  // and the incomplete marker
  }
}
