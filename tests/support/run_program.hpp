// Runs a program as a user would and captures its exit code, stdout and stderr.
#pragma once
#include <sys/types.h>

#include <string>
#include <vector>

#include "build_paths.hpp"

namespace pxflow::test {

struct RunResult {
  int exit_code = -1;  // -1 when killed by a signal
  std::string out, err;
  int err_lines() const;
};

RunResult run_program(const std::string& binary, const std::vector<std::string>& args);

// run_program with a guard: a program still running after `limit_seconds` is killed (SIGKILL)
// and its exit_code is -2. `seconds` receives how long it ran.
RunResult run_program_within(const std::string& binary, const std::vector<std::string>& args,
                             double limit_seconds, double& seconds);

// Starts a program with stdin from /dev/null and stdout, stderr into the files `out`, `err`
// (created or truncated; "/dev/null" to drop them), without waiting: its pid, for the caller to
// signal and reap.
pid_t start_program(const std::string& binary, const std::vector<std::string>& args,
                    const std::string& out, const std::string& err);

// The whole file (empty when it cannot be read).
std::string slurp(const std::string& path);

// The last line of a program's output (trailing newlines dropped).
inline std::string last_line(const std::string& out) {
  const auto end = out.find_last_not_of('\n');
  if (end == std::string::npos) return "";
  const auto start = out.rfind('\n', end);
  const auto first = start == std::string::npos ? 0 : start + 1;
  return out.substr(first, end - first + 1);
}

// The pxflow binary of this build.
inline RunResult run_pxflow(const std::vector<std::string>& args) {
  return run_program(build_paths::pxflow, args);
}

// A fresh temporary directory for one test's files (removed when the object dies).
class TempDir {
 public:
  TempDir();
  ~TempDir();
  std::string path(const std::string& name) const { return dir_ + "/" + name; }
  void write(const std::string& name, const std::string& bytes) const;

 private:
  std::string dir_;
};

}  // namespace pxflow::test
