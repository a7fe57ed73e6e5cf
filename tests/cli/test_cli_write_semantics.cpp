// Every file and every signal through one door (issue 35, items 2 and 3), by running the binary:
// an output is written where a user expects (a link at its target, its mode kept, /dev/stdout
// as "-", a device or FIFO in place, a read-only file refused before any work); temporaries are
// pxflow's own and a dead run's never block the next; every stop signal (SIGINT, SIGHUP,
// SIGPIPE, a second signal during the stop) keeps a stream's whole records and marks it
// incomplete, and a stop while waiting on input is seen at once.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <sstream>

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

namespace {

std::string sh_quoted(const std::string& s) { return std::string("'") + s + "'"; }

std::string pxflow_line(const std::vector<std::string>& args) {
  std::string s = sh_quoted(build_paths::pxflow);
  for (const std::string& a : args) s += " " + sh_quoted(a);
  return s;
}

test::RunResult sh(const std::string& script) {
  return test::run_program("/bin/sh", {"-c", script});
}

// Shell text that waits (at most 30 s) until the process $p is pxflow with its SIGINT handler in
// place (a background job of sh starts with SIGINT ignored; pxflow's handler replaces that).
const std::string kWaitForHandlers =
    "n=0; until { [ \"$(readlink /proc/$p/exe)\" = " + sh_quoted(build_paths::pxflow) +
    " ] && [ $(( 0x$(awk '/^SigCgt/{print $2}' /proc/$p/status) & 2 )) -ne 0 ]; } "
    "|| [ $n -ge 3000 ]; do sleep 0.01; n=$((n+1)); done; ";

// Shell text that waits (at most 30 s) until a temporary of `name` in `dir` holds 2 lines.
std::string wait_for_two_records(const test::TempDir& dir, const std::string& name) {
  return "n=0; until [ \"$(cat " + sh_quoted(dir.path("")) + "." + name +
         ".pxflow-*.tmp 2>/dev/null | wc -l)\" -ge 2 ] || [ $n -ge 3000 ]; do sleep 0.01; "
         "n=$((n+1)); done; ";
}

// The file `path` names itself (a link not followed): its inode and type.
std::pair<ino_t, mode_t> identity(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 ? std::pair{st.st_ino, st.st_mode & S_IFMT}
                                         : std::pair{ino_t{0}, mode_t{0}};
}

bool is_symlink(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode);
}

mode_t mode_of(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 ? st.st_mode : 0;
}

std::string listing(const test::TempDir& dir) {
  return test::run_program("/bin/ls", {"-A", dir.path("")}).out;
}

// A kept --jsonl: every line whole JSON, the last the incomplete marker counting the others.
void require_marked_jsonl(const std::string& text, const std::string& stopped_by) {
  INFO(text.substr(text.size() > 400 ? text.size() - 400 : 0));
  REQUIRE(!text.empty());
  REQUIRE(text.back() == '\n');
  std::istringstream in(text);
  std::vector<nlohmann::json> lines;
  for (std::string line; std::getline(in, line);) {
    INFO("line " << lines.size() + 1);
    REQUIRE(nlohmann::json::accept(line));
    lines.push_back(nlohmann::json::parse(line));
  }
  REQUIRE(lines.size() >= 2);
  const nlohmann::json& last = lines.back();
  REQUIRE(last.contains("incomplete"));
  CHECK(last["incomplete"]["records"] == lines.size() - 1);
  CHECK(last["incomplete"]["stopped_by"] == stopped_by);
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) CHECK(lines[i].contains("flow_x"));
}

// A process id that is surely gone: a child that exited and was reaped.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

}  // namespace

TEST_CASE("a symbolic link is written at its target, which keeps its mode", "[cli][writes]") {
  test::TempDir dir;
  dir.write("real.json", "old\n");
  REQUIRE(::chmod(dir.path("real.json").c_str(), 0600) == 0);
  REQUIRE(::symlink("real.json", dir.path("link.json").c_str()) == 0);
  const auto r = run_pxflow({"flow", "--json", dir.path("link.json"), kSamplePrev, kSampleNext});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(is_symlink(dir.path("link.json")));
  CHECK(slurp(dir.path("real.json")).find("\"flow_x\"") != std::string::npos);
  CHECK((mode_of(dir.path("real.json")) & 07777) == 0600);
  CHECK(listing(dir) == "link.json\nreal.json\n");
}

TEST_CASE("/dev/stdout and its other spellings are standard output", "[cli][writes]") {
  test::TempDir dir;
  // Whatever /dev/stdout is here (a link to /proc/self/fd/1), the run leaves it as it was.
  const auto before = identity("/dev/stdout");
  const auto r = sh(pxflow_line({"flow", "--json", "/dev/stdout", kSamplePrev, kSampleNext}) +
                    " > " + sh_quoted(dir.path("out.json")));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(nlohmann::json::parse(slurp(dir.path("out.json"))).contains("flow_x"));
  CHECK(identity("/dev/stdout") == before);  // never replaced by a file
  CHECK(listing(dir) == "out.json\n");
  require_bad_input({"flow", "--json", "/dev/stdout", "--csv", "-", kSamplePrev, kSampleNext},
                    "only one of them can write to standard output");
  require_bad_input(
      {"flow", "--json", "/dev/fd/1", "--csv", "/proc/self/fd/1", kSamplePrev, kSampleNext},
      "only one of them can write to standard output");
}

TEST_CASE("a read-only output is refused before any work and left as it was", "[cli][writes]") {
  test::TempDir dir;
  dir.write("ro.json", "mine\n");
  REQUIRE(::chmod(dir.path("ro.json").c_str(), 0444) == 0);
  require_bad_input({"flow", "--json", dir.path("ro.json"), kSamplePrev, kSampleNext},
                    "is read-only");
  dir.write("f.raw", std::string(3 * 64 * 64, '\x40'));
  require_bad_input({"flow", "--size", "64x64", "--jsonl", dir.path("ro.json"), dir.path("f.raw")},
                    "is read-only");
  CHECK(slurp(dir.path("ro.json")) == "mine\n");
  CHECK((mode_of(dir.path("ro.json")) & 07777) == 0444);
  CHECK(listing(dir) == "f.raw\nro.json\n");
}

TEST_CASE("a device or a FIFO output is written in place", "[cli][writes]") {
  const auto null = run_pxflow({"flow", "--json", "/dev/null", kSamplePrev, kSampleNext});
  CHECK(null.exit_code == 0);
  CHECK(S_ISCHR(mode_of("/dev/null")));
  test::TempDir dir;
  const std::string fifo = dir.path("out.fifo");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const auto r = sh("cat " + sh_quoted(fifo) + " > " + sh_quoted(dir.path("got.json")) +
                    " & c=$!; " + pxflow_line({"flow", "--json", fifo, kSamplePrev, kSampleNext}) +
                    " >/dev/null; echo rc=$?; wait $c");
  INFO(r.out << r.err);
  CHECK(r.out == "rc=0\n");
  CHECK(S_ISFIFO(mode_of(fifo)));
  CHECK(nlohmann::json::parse(slurp(dir.path("got.json"))).contains("flow_x"));
}

TEST_CASE("a closed pipe (SIGPIPE) stops a sequence with 141 and keeps whole records",
          "[cli][writes][signals]") {
  test::TempDir dir;
  SECTION("the lines per pair on a pipe that closes: the --jsonl file is kept, marked") {
    // An endless source: only the stop ends it (run_program_within guards against a hang).
    double seconds = 0;
    const auto r = test::run_program_within(
        "/bin/sh",
        {"-c", "cat /dev/zero | { " +
                   pxflow_line({"flow", "--size", "64x64", "--jsonl", dir.path("pk.jsonl"), "-"}) +
                   " 2>" + sh_quoted(dir.path("err.txt")) + "; echo rc=$? > " +
                   sh_quoted(dir.path("rc.txt")) + "; } | head -1"},
        120, seconds);
    INFO(r.out << slurp(dir.path("err.txt")));
    REQUIRE(r.exit_code == 0);
    CHECK(slurp(dir.path("rc.txt")) == "rc=141\n");
    require_marked_jsonl(slurp(dir.path("pk.jsonl")), "SIGPIPE");
    CHECK(slurp(dir.path("err.txt")).find("(marked incomplete)") != std::string::npos);
    CHECK(listing(dir) == "err.txt\npk.jsonl\nrc.txt\n");
  }
  SECTION("--jsonl - into a pipe that closes at once: 141, nothing left behind") {
    double seconds = 0;
    const auto r = test::run_program_within(
        "/bin/sh",
        {"-c", "cat /dev/zero | { " +
                   pxflow_line({"flow", "--size", "64x64", "--jsonl", "-", "-"}) +
                   " 2>/dev/null; echo rc=$? > " + sh_quoted(dir.path("rc.txt")) +
                   "; } | head -c 1 >/dev/null"},
        120, seconds);
    REQUIRE(r.exit_code == 0);
    CHECK(slurp(dir.path("rc.txt")) == "rc=141\n");
    CHECK(listing(dir) == "rc.txt\n");
  }
}

TEST_CASE("SIGHUP stops a sequence like SIGINT: 129, the records kept and marked",
          "[cli][writes][signals]") {
  test::TempDir dir;
  const auto r = sh("cat /dev/zero | " +
                    pxflow_line({"flow", "--size", "64x64", "--jsonl", dir.path("h.jsonl"), "-"}) +
                    " >/dev/null 2>" + sh_quoted(dir.path("err.txt")) + " & p=$!; " +
                    wait_for_two_records(dir, "h.jsonl") + "kill -HUP $p; wait $p; echo rc=$?");
  const std::string err = slurp(dir.path("err.txt"));
  INFO(r.out << err);
  CHECK(r.out == "rc=129\n");
  require_marked_jsonl(slurp(dir.path("h.jsonl")), "SIGHUP");
  CHECK(err.find("pxflow: interrupted: SIGHUP") != std::string::npos);
  CHECK(listing(dir) == "err.txt\nh.jsonl\n");
}

TEST_CASE("a second signal during the stop still keeps the records and leaves no temporary",
          "[cli][writes][signals]") {
  for (int run = 0; run < 5; ++run) {
    test::TempDir dir;
    const auto r = sh("cat /dev/zero | " +
                      pxflow_line({"flow", "--size", "64x64", "--jsonl", dir.path("d.jsonl"),
                                   "--csv", dir.path("d.csv"), "-"}) +
                      " >/dev/null 2>" + sh_quoted(dir.path("err.txt")) + " & p=$!; " +
                      wait_for_two_records(dir, "d.jsonl") +
                      "kill -INT $p; sleep 0.01; kill -INT $p; wait $p; echo rc=$?");
    INFO("run " << run << ": " << r.out << slurp(dir.path("err.txt")));
    CHECK(r.out == "rc=130\n");
    require_marked_jsonl(slurp(dir.path("d.jsonl")), "SIGINT");
    const std::string csv = slurp(dir.path("d.csv"));
    CHECK(csv.find("\n# incomplete: ") != std::string::npos);
    CHECK(csv.ends_with(" records, stopped by SIGINT\n"));
    CHECK(listing(dir) == "d.csv\nd.jsonl\nerr.txt\n");
  }
  SECTION("a second signal after the grace: the handler's last resort keeps them") {
    // Stopped, two signals, continued: the second one's handler runs during the first's stop,
    // with no grace (PXFLOW_STOP_GRACE_MS=0), as a signal does during a wind-down that hangs.
    test::TempDir dir;
    const auto r =
        sh("cat /dev/zero | PXFLOW_STOP_GRACE_MS=0 " +
           pxflow_line({"flow", "--size", "64x64", "--jsonl", dir.path("e.jsonl"), "--csv",
                        dir.path("e.csv"), "-"}) +
           " >/dev/null 2>" + sh_quoted(dir.path("err.txt")) + " & p=$!; " +
           wait_for_two_records(dir, "e.jsonl") +
           "kill -STOP $p; kill -INT $p; kill -TERM $p; kill -CONT $p; wait $p; echo rc=$?");
    const std::string err = slurp(dir.path("err.txt"));
    INFO(r.out << err);
    // Linux delivers the lower-numbered pending signal first: SIGINT stops, SIGTERM ends.
    CHECK(r.out == "rc=143\n");
    CHECK(err.find("SIGTERM during the stop") != std::string::npos);
    require_marked_jsonl(slurp(dir.path("e.jsonl")), "SIGINT");
    CHECK(slurp(dir.path("e.csv")).ends_with(" records, stopped by SIGINT\n"));
    CHECK(listing(dir) == "e.csv\ne.jsonl\nerr.txt\n");
  }
}

TEST_CASE("SIGINT while waiting on a stalled FIFO ends the run at once with 130",
          "[cli][writes][signals]") {
  test::TempDir dir;
  const std::string fifo = dir.path("in.fifo");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // The writer opens the FIFO and writes nothing for 20 s: pxflow's read waits. The shell
  // reports how long pxflow took after the signal; more than 10 s is a read that waited for the
  // writer instead.
  double seconds = 0;
  const auto r = test::run_program_within(
      "/bin/sh",
      {"-c", "(exec 3>" + sh_quoted(fifo) + "; exec sleep 20) & w=$!; " +
                 pxflow_line({"flow", "--size", "64x64", "--jsonl", dir.path("f.jsonl"), fifo}) +
                 " >/dev/null 2>" + sh_quoted(dir.path("err.txt")) + " & p=$!; " +
                 kWaitForHandlers +
                 "sleep 0.5; t0=$(date +%s); kill -INT $p; wait $p; rc=$?; "
                 "echo rc=$rc s=$(( $(date +%s) - t0 )); kill $w"},
      60, seconds);
  const std::string err = slurp(dir.path("err.txt"));
  INFO(r.out << err);
  REQUIRE(r.out.rfind("rc=130 s=", 0) == 0);
  CHECK(std::stoi(r.out.substr(9)) < 10);
  CHECK(err.find("pxflow: interrupted: SIGINT while reading") != std::string::npos);
  CHECK(listing(dir) == "err.txt\nin.fifo\n");
}

TEST_CASE("a dead run's temporaries are removed by the next run and never block it",
          "[cli][writes]") {
  test::TempDir dir;
  const std::string dead = std::to_string(dead_pid()), alive = std::to_string(::getpid());
  dir.write("x.jsonl", "previous\n");
  dir.write(".x.jsonl.pxflow-" + dead + ".tmp", "{\"half\n");
  dir.write(".x.jsonl.pxflow-" + alive + ".tmp", "a live run's\n");  // not ours to remove
  dir.write("f.raw", std::string(3 * 64 * 64, '\x40'));
  const auto r =
      run_pxflow({"flow", "--size", "64x64", "--jsonl", dir.path("x.jsonl"), dir.path("f.raw")});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(listing(dir) == ".x.jsonl.pxflow-" + alive + ".tmp\nf.raw\nx.jsonl\n");
  CHECK(slurp(dir.path("x.jsonl")).find("\"flow_x\"") != std::string::npos);

  SECTION("report --out on a folder that holds only a killed report's temporaries") {
    test::make_small_results(dir);
    REQUIRE(::mkdir(dir.path("krep").c_str(), 0755) == 0);
    dir.write("krep/.report.md.pxflow-" + dead + ".tmp", "# half a report");
    dir.write("krep/..pxflow-report.pxflow-" + dead + ".tmp", "report.md\n");
    const auto rep = run_pxflow({"report", "--out", dir.path("krep"), "--check-json",
                                 dir.path("c.json"), "--bench-json", dir.path("b.json"),
                                 "--no-accuracy", "--backends", "ref-original"});
    INFO(rep.out << rep.err);
    REQUIRE(rep.exit_code == 0);
    const std::string files = test::run_program("/bin/ls", {"-A", dir.path("krep")}).out;
    CHECK(files.find(".pxflow-" + dead + ".tmp") == std::string::npos);
    CHECK(files.find("report.md") != std::string::npos);
  }
}

TEST_CASE("a write that fails during the work: exit 1, the previous file, no claim kept",
          "[cli][writes]") {
  // `ulimit -f` stands in for a full disk: a write beyond it fails (EFBIG) as ENOSPC would.
  test::TempDir dir;
  dir.write("big.jsonl", "previous\n");
  dir.write("f.raw", std::string(400 * 64 * 64, '\x40'));
  const auto r = sh("ulimit -f 64; " +
                    pxflow_line({"flow", "--size", "64x64", "--jsonl", dir.path("big.jsonl"),
                                 dir.path("f.raw")}) +
                    " >/dev/null");
  INFO(r.err);
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("--jsonl " + dir.path("big.jsonl") + ": cannot write: File too large") !=
        std::string::npos);
  CHECK(r.err.find("kept") == std::string::npos);
  CHECK(slurp(dir.path("big.jsonl")) == "previous\n");
  CHECK(listing(dir) == "big.jsonl\nf.raw\n");
}
