// The m4-qemu row's faults (issue 17 item 5): the firmware hangs, QEMU exits or is killed, the
// link delivers garbage, the firmware speaks another protocol version, pxflow is interrupted.
// Each gives one clear line and a defined exit code within a bounded time, and leaves no QEMU
// process behind (pgrep on the firmware's path, which is unique to this build folder). The fault
// firmwares are boards/mps2-an386/dut_main.c built with M4_DUT_FAULT = 1..6 (tests/m4qemu).
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "build_paths.hpp"
#include "run_program.hpp"

namespace {

using pxflow::test::run_program;
using pxflow::test::RunResult;
using Seconds = std::chrono::duration<double>;

std::string fault_firmware(int mode) {
  return std::string(build_paths::m4_fault_dir) + "/pxflow_m4_fault" + std::to_string(mode) +
         ".elf";
}

// PIDs of QEMU processes running `firmware`.
std::vector<int> qemu_running(const std::string& firmware) {
  const RunResult r =
      run_program("/usr/bin/pgrep", {"-f", "qemu-system-arm .*-kernel " + firmware});
  std::vector<int> pids;
  std::size_t start = 0;
  while (start < r.out.size()) {
    const std::size_t end = r.out.find('\n', start);
    pids.push_back(std::stoi(r.out.substr(start, end - start)));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return pids;
}

// No QEMU of `firmware` left: the row reaps its child before pxflow exits, so none may remain
// even an instant after.
void require_no_qemu(const std::string& firmware) {
  const std::vector<int> left = qemu_running(firmware);
  INFO("QEMU processes left running " << firmware << ": " << left.size());
  REQUIRE(left.empty());
}

struct Timed {
  RunResult result;
  double seconds = 0;
};

// pxflow check on the m4-qemu row with `firmware`, the generated corpus (no files needed).
Timed check_with(const std::string& firmware, const std::string& timeout) {
  const auto t0 = std::chrono::steady_clock::now();
  Timed t;
  t.result = pxflow::test::run_pxflow({"check", "--backends", "m4-qemu", "--require", "m4-qemu",
                                       "--generated-only", "--device-timeout", timeout,
                                       "--m4-firmware", firmware});
  t.seconds = Seconds(std::chrono::steady_clock::now() - t0).count();
  return t;
}

bool mentions(const RunResult& r, const std::string& text) {
  return r.out.find(text) != std::string::npos || r.err.find(text) != std::string::npos;
}

// A pxflow check started in the background, for the faults that happen to a running row.
class Background {
 public:
  explicit Background(const std::vector<std::string>& args) {
    std::vector<std::string> argv_s = {build_paths::pxflow};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    pid_ = fork();
    if (pid_ == 0) {
      std::vector<char*> argv;
      for (auto& a : argv_s) argv.push_back(a.data());
      argv.push_back(nullptr);
      freopen("/dev/null", "w", stdout);
      freopen("/dev/null", "w", stderr);
      execv(argv[0], argv.data());
      _exit(127);
    }
  }
  ~Background() {
    if (pid_ > 0 && !reaped_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  int pid() const { return pid_; }
  // The exit status once it ended, however long that takes (a run that never ends is caught by
  // the test's hang guard, its ctest TIMEOUT).
  int wait() {
    int status = 0;
    while (waitpid(pid_, &status, 0) != pid_) {
    }
    reaped_ = true;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

 private:
  int pid_ = -1;
  bool reaped_ = false;
};

// A copy of the firmware under a path of this test's own, so that the QEMU it finds by path is
// the one its pxflow started, not another test's running the same firmware beside it (ctest -j).
class PrivateFirmware {
 public:
  PrivateFirmware() : path_(dir_.path("pxflow_m4_dut.elf")) {
    dir_.write("pxflow_m4_dut.elf", pxflow::test::slurp(build_paths::m4_firmware));
  }
  operator const std::string&() const { return path_; }

 private:
  pxflow::test::TempDir dir_;
  std::string path_;
};

// A check that keeps the row busy far longer than the faults below take to arrive: 10,000 random
// pairs (about 30 s over the semihosting link at the 300 pairs/s measured here; the generated
// corpus alone is over in 2 s, before the fault). Once the row is dead the rest fail at once.
const std::vector<std::string> kLongCheck = {"check",   "--backends", "m4-qemu", "--require",
                                             "m4-qemu", "--cases",    "10000"};

std::vector<std::string> long_check(std::vector<std::string> more) {
  std::vector<std::string> args = kLongCheck;
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// Waits until QEMU runs `firmware` (and a little longer, so that a run is under way).
std::vector<int> wait_for_qemu(const std::string& firmware, double limit) {
  const auto end = std::chrono::steady_clock::now() + Seconds(limit);
  while (std::chrono::steady_clock::now() < end) {
    const std::vector<int> pids = qemu_running(firmware);
    if (!pids.empty()) {
      std::this_thread::sleep_for(std::chrono::seconds(2));
      return pids;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return {};
}

}  // namespace

// QEMU's start-up is the HELLO wait: a firmware that never answers is a QEMU that never boots,
// given up after 4 x --device-timeout with the line naming the option.
TEST_CASE("m4-qemu: firmware that never answers: skipped, required, exit 1", "[m4][fault]") {
  const std::string fw = fault_firmware(1);
  const Timed t = check_with(fw, "0.5");
  INFO(t.result.out << t.result.err);
  CHECK(t.result.exit_code == 1);
  CHECK(mentions(t.result, "HELLO: no answer within 0.5 s after 3 resends"));
  CHECK(mentions(t.result, "slower than --device-timeout 0.5 allows: raise --device-timeout"));
  CHECK(t.seconds >= 4 * 0.5);  // it waited its 4 attempts first
  require_no_qemu(fw);
}

TEST_CASE("m4-qemu: firmware that hangs in RUN: the case fails, exit 1", "[m4][fault]") {
  const std::string fw = fault_firmware(3);
  const Timed t = check_with(fw, "2");
  INFO(t.result.out << t.result.err);
  CHECK(t.result.exit_code == 1);
  CHECK(mentions(t.result, "RUN: no answer within 2 s for 1 pair ("));
  CHECK(mentions(t.result, "--device-timeout 2 allows per 1 M candidates: raise --device-timeout"));
  CHECK(t.seconds >= 4 * 2);
  require_no_qemu(fw);
}

TEST_CASE("m4-qemu: QEMU exits in the middle of a run: the case fails, exit 1", "[m4][fault]") {
  const std::string fw = fault_firmware(2);
  const Timed t = check_with(fw, "2");
  INFO(t.result.out << t.result.err);
  CHECK(t.result.exit_code == 1);
  CHECK(mentions(t.result, "exited with status 3"));  // the firmware's board_exit(3)
  require_no_qemu(fw);
}

TEST_CASE("m4-qemu: a link that delivers garbage: not a pxflow device, exit 1", "[m4][fault]") {
  const std::string fw = fault_firmware(4);
  const Timed t = check_with(fw, "0.5");
  INFO(t.result.out << t.result.err);
  CHECK(t.result.exit_code == 1);
  CHECK(mentions(t.result, "not a pxflow device"));
  require_no_qemu(fw);
}

TEST_CASE("m4-qemu: firmware for another protocol version: skipped with both versions, exit 1",
          "[m4][fault]") {
  const std::string fw = fault_firmware(5);
  const Timed t = check_with(fw, "2");
  INFO(t.result.out << t.result.err);
  CHECK(t.result.exit_code == 1);
  CHECK(mentions(t.result, "protocol version 2, this pxflow speaks 1"));
  require_no_qemu(fw);
}

TEST_CASE("m4-qemu: a device estimate one ULP off the host's: the case fails naming both, exit 1",
          "[m4][fault]") {
  const std::string fw = fault_firmware(6);
  const Timed t = check_with(fw, "2");
  INFO(t.result.out << t.result.err);
  CHECK(t.result.exit_code == 1);
  CHECK(mentions(t.result, "differs from estimate_flow of its records"));
  require_no_qemu(fw);
}

TEST_CASE("m4-qemu: QEMU killed during a check: the case fails, exit 1, no QEMU left",
          "[m4][fault]") {
  const PrivateFirmware fw;
  Background run(long_check({"--device-timeout", "2", "--m4-firmware", fw}));
  const std::vector<int> pids = wait_for_qemu(fw, 300);
  REQUIRE(pids.size() == 1);
  kill(pids[0], SIGKILL);  // the one QEMU this test's pxflow started
  CHECK(run.wait() == 1);  // the row failed: it neither hung nor finished the campaign (exit 0)
  require_no_qemu(fw);
}

TEST_CASE("m4-qemu: Ctrl-C during a check: pxflow exits 130 and stops QEMU", "[m4][fault]") {
  const PrivateFirmware fw;
  Background run(long_check({"--m4-firmware", fw}));
  REQUIRE(wait_for_qemu(fw, 300).size() == 1);
  kill(run.pid(), SIGINT);
  CHECK(run.wait() == 130);  // stopped by the signal: a finished campaign exits 0
  require_no_qemu(fw);
}

TEST_CASE("m4-qemu: the probe says why the row cannot run", "[m4][fault]") {
  const RunResult no_fw =
      pxflow::test::run_pxflow({"backends", "--m4-firmware", "/nonexistent/pxflow_m4_dut.elf"});
  INFO(no_fw.out << no_fw.err);
  CHECK(no_fw.out.find("firmware not found: /nonexistent/pxflow_m4_dut.elf") != std::string::npos);
  const RunResult no_qemu =
      run_program("/usr/bin/env", {"PATH=/nonexistent", build_paths::pxflow, "check", "--backends",
                                   "m4-qemu", "--require", "m4-qemu", "--generated-only"});
  INFO(no_qemu.out << no_qemu.err);
  CHECK(no_qemu.exit_code == 1);
  CHECK(mentions(no_qemu, "qemu-system-arm not found in PATH"));
  const RunResult bad_link =
      pxflow::test::run_pxflow({"check", "--backends", "m4-qemu", "--m4-link", "swd"});
  INFO(bad_link.out << bad_link.err);
  CHECK(bad_link.exit_code == 2);
  CHECK(mentions(bad_link, "--m4-link: unknown link 'swd': allowed semihosting, uart"));
}
