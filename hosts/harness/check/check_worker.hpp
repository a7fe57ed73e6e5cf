// pxflow check's isolation (docs/harness.md, "Isolation"): every backend but the reference runs
// in a worker process, the pxflow binary re-executed in a hidden mode (`check --check-worker
// ROW`). The worker opens the backend, answers each case over a pipe (worker_wire.hpp) and runs
// it inside guard pages (guarded_run.hpp). pxflow itself never opens a backend, so a backend that
// crashes or hangs ends its worker, not the check.
#pragma once
#include <chrono>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "backend.hpp"
#include "guarded_child.hpp"
#include "worker_wire.hpp"

namespace pxflow::worker {

using Clock = std::chrono::steady_clock;

// The hidden option that makes `pxflow check` a worker for one row.
inline constexpr const char* kWorkerOption = "--check-worker";

// The worker's side: opens `row`, then answers cases on stdin/stdout until stdin ends. Returns
// the exit status.
int serve(const std::string& row, const BackendOptions& options);

// What came of one case.
struct Reply {
  enum class Kind { kNotApplicable, kDone, kError, kDied, kTimedOut } kind = Kind::kDone;
  std::string text;  // kNotApplicable, kError: the worker's words; kDied: "killed by SIGSEGV"
  Done done;         // kDone
  std::optional<Fault> fault;  // kDied: where the fault was, when it was in the guard pages
};

// pxflow's side: one worker process.
class WorkerProcess {
 public:
  // Starts `argv` (the worker's command line); throws SpawnError.
  explicit WorkerProcess(const std::vector<std::string>& argv);
  ~WorkerProcess();
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  // The worker's hello; a worker that ends or says nothing by `deadline` is a Reply of kind
  // kDied/kTimedOut, returned in `gone`.
  std::optional<Hello> hello(Clock::time_point deadline, Reply& gone);
  // Runs one case. Ctrl-C while waiting throws Interrupted.
  Reply run(const Params& p, std::span<const FramePair> pairs, Clock::time_point deadline);
  // Has the backend build what run() needs for `p` (Backend::prepare), so that the case's
  // allowance covers no build: kDone with done.seconds the build's time, or kNotApplicable,
  // kError, kDied, kTimedOut as for a case.
  Reply prepare(const Params& p, Clock::time_point deadline);

 private:
  // Reads one message; nullopt when the worker ended (then `gone` says how) or the deadline
  // passed (the worker is then killed).
  std::optional<Message> receive(Clock::time_point deadline, Reply& gone);
  bool send(const std::vector<std::uint8_t>& bytes, Clock::time_point deadline, Reply& gone);
  void ended(Reply& gone);
  // Sends one request and reads messages until its reply.
  Reply ask(Type type, const std::vector<std::uint8_t>& payload, Clock::time_point deadline);

  PipedChild child_;
};

}  // namespace pxflow::worker
