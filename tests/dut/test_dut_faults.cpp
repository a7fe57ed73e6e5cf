// Every fault mode of docs/dut-protocol.md section 4 against the binary: a fault the protocol
// absorbs (resend) passes; every other one is a failure line naming the device and the message,
// exit 1, within the bound --dut-timeout sets; no device process outlives the run.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <thread>

#include "dut_test_util.hpp"

extern char** environ;

using namespace pxflow::test;

namespace {

constexpr double kTimeout = 0.4;  // --dut-timeout of these runs
// A failure comes within 4 attempts of kTimeout (HELLO, then the message that fails) plus the
// work before it; 8 s covers the slowest machine without hiding a hang.
constexpr double kBound = 8.0;

struct FaultRun {
  TimedRun t;
  std::string word;
};

FaultRun run_fault(const std::string& mode, bool require = true, const std::string& cases = "40") {
  FaultRun f;
  f.word = unique_word();
  std::vector<std::string> args = {"check",
                                   "--dut",
                                   std::string("f=exec:") + DUT_FAULTY + " " + mode + " " + f.word,
                                   "--dut-timeout",
                                   std::to_string(kTimeout),
                                   "--backends",
                                   "ref-original,f",
                                   "--cases",
                                   cases};
  if (require) args.insert(args.end(), {"--require", "f"});
  f.t = timed_pxflow(args);
  return f;
}

void expect_passed(const FaultRun& f) {
  INFO(f.t.r.out << f.t.r.err);
  CHECK(f.t.r.exit_code == 0);
  CHECK_THAT(f.t.r.out, Catch::Contains("1 passed, 0 failed"));
  CHECK(f.t.seconds < kBound);
  CHECK_FALSE(process_with_word(f.word));
}

void expect_failed(const FaultRun& f, const std::string& line_part) {
  INFO(f.t.r.out << f.t.r.err);
  CHECK(f.t.r.exit_code == 1);
  CHECK_THAT(f.t.r.out, Catch::Contains("f") && Catch::Contains(line_part));
  CHECK_THAT(f.t.r.out, !Catch::Contains("1 passed"));
  CHECK(f.t.seconds < kBound);
  CHECK_FALSE(process_with_word(f.word));
}

}  // namespace

// The mode words in "N" form count the device's frames: 10 falls in the second pair.
TEST_CASE("faults the protocol absorbs: the resend succeeds", "[dut][faults]") {
  for (const std::string mode : {"none 0", "drop-byte 10", "drop-reply 10", "flip-reply 10",
                                 "flip-request 10", "garbage 10", "late 150"}) {
    INFO(mode);
    expect_passed(run_fault(mode));
  }
}

TEST_CASE("a device that answers too late fails within 4 x --dut-timeout", "[dut][faults]") {
  const FaultRun f = run_fault("late 3000");
  expect_failed(f, "dut f (exec:");
  CHECK_THAT(f.t.r.out, Catch::Contains("RUN: no answer within 0.4 s after 3 resends"));
  CHECK(f.t.seconds < 4 * kTimeout + 3.0);
}

TEST_CASE("a device that never answers, or answers noise, is skipped with its reason",
          "[dut][faults]") {
  expect_failed(run_fault("silent"), "required but cannot run: HELLO: no answer within 0.4 s");
  expect_failed(run_fault("garbage-only"), "not a pxflow device");
  const FaultRun skipped = run_fault("silent", false);
  INFO(skipped.t.r.out << skipped.t.r.err);
  CHECK_THAT(skipped.t.r.out, Catch::Contains("skip f (HELLO: no answer"));
  CHECK_FALSE(process_with_word(skipped.word));
}

TEST_CASE("a device of another protocol version is skipped naming both versions", "[dut][faults]") {
  expect_failed(run_fault("version"), "protocol version 2, this pxflow speaks 1");
  const FaultRun skipped = run_fault("version", false);
  CHECK_THAT(skipped.t.r.out, Catch::Contains("skip f (protocol version 2, this pxflow speaks 1)"));
}

TEST_CASE("a device that resets or exits mid-run fails with what happened", "[dut][faults]") {
  expect_failed(run_fault("reset 10"), "ERROR 4");
  expect_failed(run_fault("reset 10"), "did it reset?");
  expect_failed(run_fault("exit 10"), "exited with status 3");
}

TEST_CASE("short or extra records and a wrong count never pass", "[dut][faults]") {
  expect_failed(run_fault("short-result"), "says 63 records, the grid has 64");
  expect_failed(run_fault("short-records"), "RECORDS: RECORDS reply has");
  expect_failed(run_fault("extra-records"), "RECORDS: RECORDS reply has");
}

TEST_CASE("a wrong field is the usual mismatch line, a wrong estimate names both",
          "[dut][faults]") {
  const FaultRun field = run_fault("wrong-field 3");
  expect_failed(field, "sub[3]");
  expect_failed(run_fault("wrong-estimate"), "the device's estimate of pair 0");
}

TEST_CASE("Ctrl-C stops pxflow and its device at once", "[dut][faults]") {
  const std::string word = unique_word();
  std::vector<std::string> args = {
      PXFLOW_BINARY,   "check",
      "--dut",         std::string("f=exec:") + DUT_FAULTY + " late 60000 " + word,
      "--dut-timeout", "30",
      "--backends",    "ref-original,f",
      "--cases",       "300"};  // two cases: the second sees the signal
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  REQUIRE(posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ) == 0);
  posix_spawn_file_actions_destroy(&fa);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // in RUN, waiting
  CHECK(process_with_word(word));
  const auto t0 = std::chrono::steady_clock::now();
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK(s < 3.0);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 130);
  CHECK_FALSE(process_with_word(word));
}
