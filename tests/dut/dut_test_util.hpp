// Running pxflow against the test devices: timed runs, devices started beside pxflow (tcp, pty),
// and the check that no device process outlived its run.
#pragma once
#include <sys/types.h>

#include <string>
#include <vector>

#include "run_program.hpp"

namespace pxflow::test {

struct TimedRun {
  RunResult r;
  double seconds = 0;
};
TimedRun timed_pxflow(const std::vector<std::string>& args);

// A device program started with its stdout on a pipe; first_line() is what it printed first
// (its TCP port or its pty's path). The destructor stops it (SIGTERM, then SIGKILL) and reaps it.
class BesideDevice {
 public:
  BesideDevice(const std::vector<std::string>& argv);
  ~BesideDevice();
  const std::string& first_line() const { return line_; }
  // Waits up to `seconds` for it to exit by itself; its exit status, or -1.
  int wait_exit(double seconds);

 private:
  pid_t pid_ = -1;
  int out_ = -1;
  std::string line_;
  bool reaped_ = false;
};

// A word unique to this test process, to pass to a device so that process_with_word() finds it.
std::string unique_word();
// Whether a process whose command line contains `word` exists (an orphan of a finished run),
// other than `except` (pxflow itself, whose --dut argument holds the word too).
bool process_with_word(const std::string& word, pid_t except = -1);
// Whether a process whose command line contains `word` runs another program than pxflow: the
// device, not pxflow or its guardian (a fork of pxflow: hosts/core/guarded_child.hpp).
bool device_with_word(const std::string& word);
// Whether process `pid` has ended (gone, or a zombie nobody reaped yet).
bool process_ended(pid_t pid);
// pxflow started with `args`, its output thrown away; its pid, for the caller to signal and reap.
pid_t spawn_quiet_pxflow(const std::vector<std::string>& args);

}  // namespace pxflow::test
