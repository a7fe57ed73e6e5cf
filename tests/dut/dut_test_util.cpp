#include "dut_test_util.hpp"

#include <dirent.h>
#include <limits.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "build_paths.hpp"

extern char** environ;

namespace pxflow::test {

TimedRun timed_pxflow(const std::vector<std::string>& args) {
  const auto t0 = std::chrono::steady_clock::now();
  TimedRun t;
  t.r = run_pxflow(args);
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return t;
}

BesideDevice::BesideDevice(const std::vector<std::string>& args) {
  int p[2];
  if (pipe(p) != 0) throw std::runtime_error("pipe");
  std::vector<std::string> copy = args;
  std::vector<char*> argv;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, p[1], 1);
  posix_spawn_file_actions_addclose(&fa, p[0]);
  const int rc = posix_spawn(&pid_, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  close(p[1]);
  out_ = p[0];
  if (rc != 0) throw std::runtime_error("cannot start " + args[0]);
  // Its first line, within 10 s.
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  char c;
  while (std::chrono::steady_clock::now() < until) {
    pollfd pf{out_, POLLIN, 0};
    if (poll(&pf, 1, 100) <= 0) continue;
    if (read(out_, &c, 1) != 1 || c == '\n') break;
    line_ += c;
  }
}

int BesideDevice::wait_exit(double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int st = 0;
  while (std::chrono::steady_clock::now() < until) {
    if (waitpid(pid_, &st, WNOHANG) == pid_) {
      reaped_ = true;
      return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return -1;
}

BesideDevice::~BesideDevice() {
  if (!reaped_ && pid_ > 0) {
    kill(pid_, SIGTERM);
    if (wait_exit(2) < 0 && !reaped_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  if (out_ >= 0) close(out_);
}

std::string unique_word() {
  static std::atomic<int> n{0};
  return "dut-test-" + std::to_string(getpid()) + "-" + std::to_string(n++);
}

namespace {

// Whether a process other than `except` has `word` in its command line and is accepted by
// `wanted` (given its /proc folder).
template <typename Wanted>
bool process_with_word_where(const std::string& word, pid_t except, Wanted wanted) {
  DIR* d = opendir("/proc");
  if (!d) return false;
  bool found = false;
  while (dirent* e = readdir(d)) {
    if (e->d_name[0] < '0' || e->d_name[0] > '9' || std::atoi(e->d_name) == except) continue;
    const std::string dir = std::string("/proc/") + e->d_name;
    if (slurp(dir + "/cmdline").find(word) != std::string::npos && wanted(dir)) found = true;
  }
  closedir(d);
  return found;
}

std::string exe_of(const std::string& proc_dir) {
  char buf[4096];
  const ssize_t n = readlink((proc_dir + "/exe").c_str(), buf, sizeof buf);
  return n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
}

}  // namespace

bool process_with_word(const std::string& word, pid_t except) {
  return process_with_word_where(word, except, [](const std::string&) { return true; });
}

bool device_with_word(const std::string& word) {
  char pxflow[PATH_MAX];
  const std::string self = realpath(build_paths::pxflow, pxflow) ? pxflow : build_paths::pxflow;
  return process_with_word_where(word, -1,
                                 [&](const std::string& dir) { return exe_of(dir) != self; });
}

bool process_ended(pid_t pid) {
  const std::string stat = slurp("/proc/" + std::to_string(pid) + "/stat");
  const auto paren = stat.rfind(')');  // "PID (COMM) STATE ...": COMM may hold anything
  return paren == std::string::npos || stat.compare(paren + 1, 2, " Z") == 0;
}

pid_t spawn_quiet_pxflow(const std::vector<std::string>& args) {
  return start_program(build_paths::pxflow, args, "/dev/null", "/dev/null");
}

}  // namespace pxflow::test
