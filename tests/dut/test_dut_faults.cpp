// Every fault mode of docs/dut-protocol.md section 4 against the binary: a fault the protocol
// absorbs (resend) passes; every other one is a failure line naming the device and the message,
// exit 1, after the allowance --device-timeout sets; no device process outlives the run. A slow
// device that keeps sending keepalives is not hung.
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

// --device-timeout of these runs. No test here bounds how long a run takes (a loaded machine
// makes any run slow): a hang is a device that never answers in time, and the test shows that
// pxflow gave up (the line, the exit code, the device gone) and waited its allowance first.
constexpr double kTimeout = 0.4;

struct FaultRun {
  TimedRun t;
  std::string word;
};

FaultRun run_fault(const std::string& mode, bool require = true, const std::string& cases = "40",
                   double timeout = kTimeout) {
  FaultRun f;
  f.word = unique_word();
  std::vector<std::string> args = {"check",
                                   "--dut",
                                   std::string("f=exec:") + DUT_FAULTY + " " + mode + " " + f.word,
                                   "--device-timeout",
                                   std::to_string(timeout),
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
  CHECK_FALSE(process_with_word(f.word));
}

void expect_failed(const FaultRun& f, const std::string& line_part) {
  INFO(f.t.r.out << f.t.r.err);
  CHECK(f.t.r.exit_code == 1);
  CHECK_THAT(f.t.r.out, Catch::Contains("f") && Catch::Contains(line_part));
  CHECK_THAT(f.t.r.out, !Catch::Contains("1 passed"));
  CHECK_FALSE(process_with_word(f.word));
}

}  // namespace

// The mode words in "N" form count the device's frames: 10 falls in the second pair.
TEST_CASE("faults the protocol absorbs: the resend succeeds", "[dut][faults]") {
  for (const std::string mode : {"none 0", "drop-byte 10", "drop-reply 10", "flip-reply 10",
                                 "flip-request 10", "garbage 10"}) {
    INFO(mode);
    expect_passed(run_fault(mode));
  }
  expect_passed(run_fault("late 150", true, "8"));  // 150 ms per RESULT, within the timeout
}

TEST_CASE("a device that answers too late fails after 4 x --device-timeout", "[dut][faults]") {
  // The device would answer a minute late; had pxflow waited for it, the case would pass.
  const FaultRun f = run_fault("late 60000", true, "1");
  expect_failed(f, "dut f (exec:");
  // The px4flow-64 case's RUN is less than one work unit: its wait is the timeout itself.
  CHECK_THAT(f.t.r.out, Catch::Contains("RUN: no answer within 0.4 s for 1 pair (") &&
                            Catch::Contains(" POIs at S=") &&
                            Catch::Contains("after 3 resends (each waited up to 0.4 s)") &&
                            Catch::Contains("the device hangs or is slower than --device-timeout "
                                            "0.4 allows per 1 M candidates: raise "
                                            "--device-timeout"));
  CHECK(f.t.seconds >= 4 * kTimeout);  // it waited its 4 attempts before giving up
}

TEST_CASE("a device that answers slowly but sends keepalives is not hung", "[dut][faults]") {
  // Each RESULT 6 s late, 3 x the 2 s timeout, with a keepalive every 0.1 s: every keepalive
  // restarts the wait, so no wait ever fires and the case passes. Margins for a loaded machine:
  // a keepalive would have to be 2 s late (20 x its period) for a wait to fire.
  const FaultRun f = run_fault("slow-alive 6000", true, "1", 2.0);
  expect_passed(f);
  CHECK(f.t.seconds > 6);  // the device did take its time
}

TEST_CASE("a device that never answers, or answers noise, is skipped with its reason",
          "[dut][faults]") {
  const FaultRun silent = run_fault("silent");
  expect_failed(silent, "required but cannot run: HELLO: no answer within 0.4 s");
  CHECK_THAT(silent.t.r.out, Catch::Contains("after 3 resends (each waited up to 0.4 s); is the "
                                             "device running and on this link (baud rate)? the "
                                             "device hangs or is slower than --device-timeout "
                                             "0.4 allows: raise --device-timeout"));
  expect_failed(run_fault("garbage-only"), "not a pxflow device");
  const FaultRun skipped = run_fault("silent", false);
  INFO(skipped.t.r.out << skipped.t.r.err);
  CHECK_THAT(skipped.t.r.out, Catch::Contains("skip f (HELLO: no answer"));
  CHECK_FALSE(process_with_word(skipped.word));
}

TEST_CASE("a device that does not copy seq is told so, not 'no answer'", "[dut][faults]") {
  expect_failed(run_fault("wrong-seq"), "RUN: only a reply with seq ");
  expect_failed(run_fault("wrong-seq"), "(a reply copies its request's seq)");
}

TEST_CASE("a dead device's line is given once, then repeated as it was", "[dut][faults]") {
  // Dies in the first case's second pair; the fixed corpus's 7 other 64x64 cases follow.
  const std::string word = unique_word();
  const RunResult r =
      timed_pxflow({"check", "--dut", std::string("f=exec:") + DUT_FAULTY + " exit 10 " + word,
                    "--backends", "ref-original,f", "--generated-only"})
          .r;
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.out, Catch::Contains("(its output above may say why) (failed earlier in this run)"));
  CHECK_THAT(r.out, !Catch::Contains("(failed earlier in this run) (failed earlier"));
  CHECK_FALSE(process_with_word(word));
}

TEST_CASE("a program that prints anything but frames is given up after a bounded read",
          "[dut][faults]") {
  // yes(1) writes "y\n" without end and never a delimiter: the host reads a bounded amount (four
  // of its largest frames, 262,160 bytes, plus at most one read of 4,096) and says what to check.
  const RunResult r = timed_pxflow({"check", "--dut", "y=exec:/usr/bin/yes", "--backends",
                                    "ref-original,y", "--require", "y", "--generated-only"})
                          .r;
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  const std::string line = "not a pxflow device: ";
  const auto at = r.out.find(line);
  REQUIRE(at != std::string::npos);
  CHECK(std::stoull(r.out.substr(at + line.size())) <= 262160u + 4096u);
  CHECK_THAT(r.out, Catch::Contains("does the program write only protocol frames to its stdout?"));
  CHECK_THAT(r.out, !Catch::Contains("baud rate"));
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
  std::vector<std::string> args = {PXFLOW_BINARY,
                                   "check",
                                   "--dut",
                                   std::string("f=exec:") + DUT_FAULTY + " late 600000 " + word,
                                   "--device-timeout",
                                   "300",
                                   "--backends",
                                   "ref-original,f",
                                   "--cases",
                                   "300"};  // two cases: the second sees the signal
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
  // Until the device runs (pxflow starts slowly on a loaded machine), then into the RUN it
  // answers ten minutes late, with 300 s allowed per attempt.
  for (int i = 0; i < 6000 && !process_with_word(word, pid); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  REQUIRE(process_with_word(word, pid));
  std::this_thread::sleep_for(std::chrono::milliseconds(800));
  const auto t0 = std::chrono::steady_clock::now();
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Not a speed bound: without the signal the run would wait 300 s for the device (the exit
  // status alone cannot tell, pxflow exits 130 either way); it stops at the signal instead.
  CHECK(s < 60.0);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 130);
  CHECK_FALSE(process_with_word(word));
}
