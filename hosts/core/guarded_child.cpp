#include "guarded_child.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <string_view>
#include <thread>

// Between fork and exec (or _exit) a process forked from a multithreaded pxflow may only make
// async-signal-safe calls: the child and the guardian below use system calls alone.

namespace pxflow {
namespace {

std::string os_error(const std::string& what) { return what + ": " + std::strerror(errno); }

void close_pipe(int p[2]) {
  if (p[0] >= 0) ::close(p[0]);
  if (p[1] >= 0) ::close(p[1]);
  p[0] = p[1] = -1;
}

// A read of one byte that a signal does not cut short; what read() returned.
ssize_t read_byte(int fd) {
  char c;
  ssize_t n;
  do n = ::read(fd, &c, 1);
  while (n < 0 && errno == EINTR);
  return n;
}

void sleep_ms(long ms) {
  timespec t{0, ms * 1000000L};
  while (nanosleep(&t, &t) != 0 && errno == EINTR) {
  }
}

// The guardian's wake-up: the parent-death signal only interrupts its poll.
extern "C" void on_wake(int) {}
constexpr int kParentDeathSignal = SIGUSR1;

// Every descriptor but `keep` closed, `keep` moved to 3: the guardian holds no pipe anyone waits
// on for an end of file (pxflow's stdout, another device's link).
int keep_only(int keep) {
  if (keep != 3) {
    dup2(keep, 3);
    keep = 3;
  }
  for (int fd = 0; fd < 3; ++fd) ::close(fd);
  if (close_range(4, ~0u, 0) != 0) {
    rlimit r{};
    const rlim_t top = getrlimit(RLIMIT_NOFILE, &r) == 0 && r.rlim_cur != RLIM_INFINITY
                           ? r.rlim_cur
                           : static_cast<rlim_t>(65536);
    for (rlim_t fd = 4; fd < top; ++fd) ::close(static_cast<int>(fd));
  }
  return keep;
}

// SIGTERM to the group (a wrapper script may stop what it started), SIGKILL to what is left
// after a second.
[[noreturn]] void end_group(pid_t group) {
  kill(-group, SIGTERM);
  for (int i = 0; i < 50; ++i) {
    if (kill(-group, 0) != 0 && errno == ESRCH) _exit(0);
    sleep_ms(20);
  }
  kill(-group, SIGKILL);
  _exit(0);
}

// The guardian: waits until pxflow is gone, then ends the device's process group. pxflow is
// gone when the pipe whose only write end pxflow holds reads end of file (pxflow ended, any
// way), when the parent-death signal comes, or when this process was handed to another parent
// (checked every half second as well: a last line that needs neither).
[[noreturn]] void guard(int lifeline, pid_t group, pid_t pxflow) {
  struct sigaction wake {};
  wake.sa_handler = on_wake;
  sigemptyset(&wake.sa_mask);
  sigaction(kParentDeathSignal, &wake, nullptr);
  // Ctrl-C and the like reach pxflow's whole process group, this process too: pxflow stops the
  // device itself then, and this process waits until pxflow is gone.
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  for (const int sig : {SIGINT, SIGTERM, SIGQUIT, SIGHUP, SIGTSTP, SIGTTIN, SIGTTOU, SIGPIPE})
    sigaction(sig, &ignore, nullptr);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
#ifdef __linux__
  prctl(PR_SET_PDEATHSIG, kParentDeathSignal);
#endif
  lifeline = keep_only(lifeline);
  while (getppid() == pxflow) {
    pollfd p{lifeline, POLLIN, 0};
    const int r = poll(&p, 1, 500);
    if (r > 0 && read_byte(lifeline) <= 0) break;  // end of file: pxflow's end is closed
    if (r < 0 && errno != EINTR) sleep_ms(500);    // cannot poll: getppid() alone watches
  }
  end_group(group);
}

// `fd` as the child's descriptor `target`, kept open across exec.
void onto(int fd, int target) {
  if (fd == target)
    fcntl(fd, F_SETFD, 0);
  else
    dup2(fd, target);
}

// The device's side of the fork: its own process group, the parent-death signal (it dies with
// pxflow even before the guardian could act), then it waits for the guardian to be watching
// before it runs anything that could start processes of its own.
[[noreturn]] void exec_child(char* const* argv, int in, int out, int err, int gate, int exec_errno,
                             pid_t pxflow) {
  setpgid(0, 0);  // Ctrl-C goes to pxflow, which stops the device itself
#ifdef __linux__
  prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
  if (getppid() != pxflow || read_byte(gate) != 1) _exit(127);  // pxflow is already gone
  onto(in, 0);
  onto(out, 1);
  if (err >= 0) onto(err, 2);
  signal(SIGPIPE, SIG_DFL);  // pxflow ignores it; the device gets the usual default
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  execvp(argv[0], argv);
  const int e = errno;
  (void)!::write(exec_errno, &e, sizeof e);
  _exit(127);
}

}  // namespace

GuardedChild::GuardedChild(const std::vector<std::string>& args, int stdin_fd, int stdout_fd,
                           int stderr_fd) {
  if (args.empty()) throw SpawnError("cannot start a child: no program given");
  const std::string& name = args[0];
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  signal(SIGPIPE, SIG_IGN);  // a child that ended is a write error, not the end of pxflow
  // gate: the guardian is watching, the child may exec; exec_errno: closed by a successful exec,
  // else it carries exec's errno; lifeline: the guardian's pipe.
  int gate[2] = {-1, -1}, exec_errno[2] = {-1, -1}, lifeline[2] = {-1, -1};
  if (pipe2(gate, O_CLOEXEC) != 0 || pipe2(exec_errno, O_CLOEXEC) != 0 ||
      pipe2(lifeline, O_CLOEXEC) != 0) {
    const std::string why = os_error("cannot start " + name + ": pipe");
    close_pipe(gate), close_pipe(exec_errno), close_pipe(lifeline);
    throw SpawnError(why);
  }
  const pid_t self = getpid();
  int fork_errno = 0;
  pid_ = fork();
  if (pid_ < 0) fork_errno = errno;
  if (pid_ == 0) {
    ::close(gate[1]), ::close(lifeline[0]), ::close(lifeline[1]), ::close(exec_errno[0]);
    exec_child(argv.data(), stdin_fd, stdout_fd, stderr_fd, gate[0], exec_errno[1], self);
  }
  ::close(exec_errno[1]);  // the child's alone now: its end of file is a successful exec
  if (pid_ > 0) {
    setpgid(pid_, pid_);  // both sides set it: whichever runs first, the group exists after
    guardian_ = fork();
    if (guardian_ == 0) guard(lifeline[0], pid_, self);
    if (guardian_ < 0) fork_errno = errno;
  }
  ::close(lifeline[0]);
  lifeline_ = lifeline[1];
  std::string why_not;  // why the child was not let run
  if (pid_ < 0 || guardian_ < 0)
    why_not = "fork: " + std::string(std::strerror(fork_errno));
  else if (::write(gate[1], "g", 1) != 1)  // the child ended (EPIPE)
    why_not = "it ended before it ran";
  const bool started = why_not.empty();
  close_pipe(gate);
  int e = 0;
  ssize_t n = 0;
  if (started) {
    do n = ::read(exec_errno[0], &e, sizeof e);
    while (n < 0 && errno == EINTR);
  }
  ::close(exec_errno[0]);
  if (!started || n == static_cast<ssize_t>(sizeof e)) {
    stop();
    throw SpawnError("cannot start " + name + ": " + (started ? std::strerror(e) : why_not));
  }
}

void GuardedChild::reap(int flags) {
  int st = 0;
  pid_t r;
  do r = waitpid(pid_, &st, flags);
  while (r < 0 && errno == EINTR);
  if (r == pid_ || (r < 0 && errno == ECHILD)) reaped_ = true, status_ = st;
}

bool GuardedChild::exited(std::chrono::milliseconds wait) {
  const auto deadline = std::chrono::steady_clock::now() + wait;
  while (!reaped_ && pid_ > 0) {
    reap(WNOHANG);
    if (reaped_ || std::chrono::steady_clock::now() >= deadline) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return reaped_;
}

void GuardedChild::stop() {
  if (pid_ > 0) {
    kill(-pid_, SIGKILL);  // the group: whatever the command started goes too
    if (!reaped_) reap(0);
  }
  if (guardian_ > 0) {  // its work is done: the group is gone
    kill(guardian_, SIGKILL);
    while (waitpid(guardian_, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  if (lifeline_ >= 0) ::close(lifeline_);
  pid_ = guardian_ = lifeline_ = -1;
}

PipedChild start_piped_child(const std::vector<std::string>& argv, bool capture_stderr) {
  int to_child[2] = {-1, -1}, from_child[2] = {-1, -1}, errors[2] = {-1, -1};
  if (pipe2(to_child, O_CLOEXEC) != 0 || pipe2(from_child, O_CLOEXEC) != 0 ||
      (capture_stderr && pipe2(errors, O_CLOEXEC) != 0)) {
    const std::string why = os_error("cannot start " + (argv.empty() ? "" : argv[0]) + ": pipe");
    close_pipe(to_child), close_pipe(from_child), close_pipe(errors);
    throw SpawnError(why);
  }
  PipedChild c;
  try {
    c.child = std::make_unique<GuardedChild>(argv, to_child[0], from_child[1], errors[1]);
  } catch (const SpawnError&) {
    close_pipe(to_child), close_pipe(from_child), close_pipe(errors);
    throw;
  }
  ::close(to_child[0]);
  ::close(from_child[1]);
  if (errors[1] >= 0) ::close(errors[1]);
  c.to_child = to_child[1];
  c.from_child = from_child[0];
  c.errors_from_child = errors[0];
  return c;
}

std::string ended_text(int status) {
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) {
    const char* name = sigabbrev_np(WTERMSIG(status));
    return "killed by " +
           (name ? "SIG" + std::string(name) : "signal " + std::to_string(WTERMSIG(status)));
  }
  return "ended with wait status " + std::to_string(status);
}

std::string own_executable() {
  std::error_code e;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", e);
  if (e) throw SpawnError("cannot find the pxflow binary (/proc/self/exe): " + e.message());
  return self.string();
}

std::string own_command_name() {
  namespace fs = std::filesystem;
  fs::path self;
  try {
    self = own_executable();
  } catch (const SpawnError&) {
    return "pxflow";
  }
  std::error_code e;
  const std::string argv0 = program_invocation_name;  // glibc's argv[0], as started
  const char* path = std::getenv("PATH");
  if (argv0.empty() || argv0.find('/') != std::string::npos || !path) return self.string();
  // The first folder on PATH with that name is the one a shell would run.
  for (std::string_view rest = path; !rest.empty();) {
    const std::size_t colon = rest.find(':');
    const std::string dir(rest.substr(0, colon));
    rest = colon == std::string_view::npos ? std::string_view() : rest.substr(colon + 1);
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / argv0;
    if (::access(candidate.c_str(), X_OK) != 0) continue;
    return fs::equivalent(candidate, self, e) ? argv0 : self.string();
  }
  return self.string();
}

}  // namespace pxflow
