// Every fault mode of docs/dut-protocol.md section 4 against the binary: a fault the protocol
// absorbs (resend) passes; every other one is a failure line naming the device and the message,
// exit 1, after the allowance --device-timeout sets; no device process outlives the run. A slow
// device that keeps sending keepalives is not hung.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <thread>

#include "build_paths.hpp"
#include "dut_test_util.hpp"

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
  std::vector<std::string> args = {
      "check",
      "--dut",
      std::string("f=exec:") + build_paths::dut_faulty + " " + mode + " " + f.word,
      "--device-timeout",
      std::to_string(timeout),
      "--backends",
      "ref-original,f",
      "--cases",
      cases,
      "--no-repro"};  // no reproducer folder in the test's folder
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
      timed_pxflow({"check", "--dut",
                    std::string("f=exec:") + build_paths::dut_faulty + " exit 10 " + word,
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
  // A record more than asked is a write past the output (the stream's guard zone).
  expect_failed(run_fault("extra-records"), "wrote past its output (32 bytes after record");
  expect_failed(run_fault("overrun"), "ERROR 7 (the kernel wrote past the run's records)");
}

TEST_CASE("a wrong field is the usual mismatch line, a wrong estimate names both",
          "[dut][faults]") {
  const FaultRun field = run_fault("wrong-field 3");
  expect_failed(field, "sub[3]");
  expect_failed(run_fault("wrong-estimate"), "the device's estimate of pair 0");
}

namespace {

// pxflow checking the device `exec` (a --dut value, holding `word`), which answers its first RUN
// ten minutes late, with 300 s allowed per attempt: its pid once the device runs and pxflow is
// waiting in that RUN.
pid_t pxflow_waiting_on(const std::string& exec, const std::string& word) {
  const pid_t pid = spawn_quiet_pxflow({"check", "--dut", "f=exec:" + exec, "--device-timeout",
                                        "300", "--backends", "ref-original,f", "--cases",
                                        "300"});  // two cases: the second sees the signal
  // Until the device runs (pxflow starts slowly on a loaded machine), then into its RUN.
  for (int i = 0; i < 6000 && !device_with_word(word); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  REQUIRE(device_with_word(word));
  std::this_thread::sleep_for(std::chrono::milliseconds(800));
  return pid;
}

}  // namespace

TEST_CASE("Ctrl-C stops pxflow and its device at once", "[dut][faults]") {
  const std::string word = unique_word();
  const pid_t pid =
      pxflow_waiting_on(std::string(build_paths::dut_faulty) + " late 600000 " + word, word);
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

TEST_CASE("no device is left behind a wrapper when pxflow is killed with SIGKILL",
          "[dut][faults]") {
  // The wrapper a porter may write: the device runs as a child of a subshell (not exec), two
  // levels below the process pxflow started; each level writes its pid into a file.
  const TempDir dir;
  dir.write("wrapper.sh",
            "#!/bin/sh\n"
            "dir=$1; shift\n"
            "echo $$ > \"$dir/wrapper\"\n"
            "exec 3<&0\n"  // a background job's stdin would be /dev/null
            "(\n"
            "  \"$@\" <&3 3<&- &\n"
            "  echo $! > \"$dir/device\"\n"
            "  wait\n"
            ") &\n"
            "echo $! > \"$dir/subshell\"\n"
            "wait\n");
  const std::string word = unique_word();
  const pid_t pid = pxflow_waiting_on("/bin/sh " + dir.path("wrapper.sh") + " " + dir.path(".") +
                                          " " + build_paths::dut_faulty + " late 600000 " + word,
                                      word);
  std::vector<pid_t> started;
  for (const char* level : {"wrapper", "subshell", "device"}) {
    for (int i = 0; i < 600 && slurp(dir.path(level)).empty(); ++i)  // written as it started
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    started.push_back(std::stoi(slurp(dir.path(level))));
  }
  for (const pid_t p : started) REQUIRE_FALSE(process_ended(p));
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  // A hang guard, not a speed bound: everything is gone within moments; a survivor would never go.
  const auto all_ended = [&] {
    for (const pid_t p : started)
      if (!process_ended(p)) return false;
    return !process_with_word(word);  // pxflow's guardian too
  };
  for (int i = 0; i < 600 && !all_ended(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  for (const pid_t p : started) CHECK(process_ended(p));
  CHECK_FALSE(process_with_word(word));
}

TEST_CASE("a bench whose only row's records differ times nothing and exits 1", "[dut][faults]") {
  // The device answers its first run (the bench's check before timing) with a wrong field.
  const auto r = run_pxflow(
      {"bench", "--dut",
       std::string("f=exec:") + build_paths::dut_faulty + " wrong-field 1 " + unique_word(),
       "--backends", "f", "--batch", "1", "--sizes", "64x64", "--min-time", "0"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("not timed: records differ") != std::string::npos);
  CHECK(r.out.find("1 row not timed because its records differ") != std::string::npos);
}
