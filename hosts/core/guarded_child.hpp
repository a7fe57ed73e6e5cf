// The one way pxflow starts a child process (an exec: device, QEMU for m4-qemu): the child runs
// in a process group of its own, watched by a guardian process that kills that whole group when
// pxflow ends, however it ends (SIGKILL included). So nothing a wrapper script or a forked child
// started outlives pxflow; only a program that leaves the group itself (setsid, setpgid) escapes
// (docs/dut-protocol.md, "exec:").
#pragma once
#include <sys/types.h>

#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace pxflow {

// The child could not be started: "cannot start PROGRAM: why".
struct SpawnError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class GuardedChild {
 public:
  // Starts argv (argv[0] searched in PATH, no shell) with `stdin_fd` as its standard input and
  // `stdout_fd` as its standard output; its standard error is `stderr_fd`, or pxflow's when -1.
  // The caller keeps (and closes) the descriptors. pxflow ignores SIGPIPE from then on: writing to
  // a child that ended is an error to report, not the end of pxflow.
  GuardedChild(const std::vector<std::string>& argv, int stdin_fd, int stdout_fd,
               int stderr_fd = -1);
  ~GuardedChild() { stop(); }
  GuardedChild(const GuardedChild&) = delete;
  GuardedChild& operator=(const GuardedChild&) = delete;

  // Whether the child has exited, waiting up to `wait` for it; reaps it when it has.
  bool exited(std::chrono::milliseconds wait);
  // Its wait status (waitpid's), once exited() said true.
  int status() const { return status_; }
  // Kills the child's process group (SIGKILL), reaps the child, releases the guardian. Safe to
  // call twice.
  void stop();

 private:
  void reap(int flags);
  pid_t pid_ = -1;
  pid_t guardian_ = -1;
  int lifeline_ = -1;  // the one write end of the guardian's pipe: its EOF means pxflow is gone
  bool reaped_ = false;
  int status_ = 0;
};

// A GuardedChild with a pipe each way: pxflow writes to `to_child` (the child's stdin) and reads
// `from_child` (its stdout). Both descriptors are pxflow's to close (close-on-exec).
struct PipedChild {
  std::unique_ptr<GuardedChild> child;
  int to_child = -1;
  int from_child = -1;
  int errors_from_child = -1;  // the child's stderr, when asked for; else -1
};
// Throws SpawnError ("cannot start PROGRAM: why"). `capture_stderr`: the child's standard error
// is a pipe too (`errors_from_child`), not pxflow's.
PipedChild start_piped_child(const std::vector<std::string>& argv, bool capture_stderr = false);

// How a child ended, from its wait status: "exited with status 3", "killed by SIGSEGV".
std::string ended_text(int wait_status);

// The running pxflow binary (/proc/self/exe), to re-execute itself (pxflow check's workers);
// throws SpawnError when it cannot be read.
std::string own_executable();

// This binary as a printed command should name it (reproducers, resume hints): the bare name it
// was started under when PATH finds this very binary under that name, else its absolute path;
// "pxflow" only when /proc/self/exe cannot be read. Not shell-quoted.
std::string own_command_name();

}  // namespace pxflow
