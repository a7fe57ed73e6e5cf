// One row of `pxflow check` run in its worker process (check_worker.hpp), turned into what the
// checker needs: records to compare, "n/a", or the line of a failure whatever the backend did
// (threw, crashed, wrote outside its output, never returned). docs/harness.md, "Isolation".
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "check_corpus.hpp"
#include "check_worker.hpp"
#include "device_wait.hpp"

namespace pxflow {

struct IsolationOptions {
  // The worker's command line but the row: the pxflow binary, the global options, `check`,
  // --threads and --device as given (check_worker.hpp appends --check-worker ROW).
  std::vector<std::string> worker_command;
  double case_timeout = 0;  // > 0: --case-timeout, the fixed allowance of every case
};

// How long a worker may take to open its backend and say hello (a GPU driver's set-up, QEMU's
// boot): opening is not a case, so no case's allowance applies.
inline constexpr double kOpenSeconds = 300;
// The allowance of a case (docs/harness.md, "Isolation"): 2 x --device-timeout per work unit
// (device_wait.hpp's rule) plus kSlowMargin times the case's reference time times the row's
// slowest measured ratio to the reference so far (kFirstRatio before it has one).
inline constexpr double kSlowMargin = 20;
// How long a worker may take to build a case's kernels before the case runs (Backend::prepare:
// vulkan compiles up to two pipelines, each allowed kBuildSeconds by its own wait), apart from
// the case's allowance: a build is not the case's work (docs/harness.md, "Isolation").
inline constexpr double kPrepareSeconds = 2 * kBuildSeconds + 60;
inline constexpr double kFirstRatio = 1000;

class IsolatedRow {
 public:
  IsolatedRow(std::string row, const IsolationOptions& options);

  // Starts the worker; `opened` waits for its hello.
  void start();
  struct Opened {
    bool ok = false;
    bool failed = false;  // its worker died or did not answer (a failure, not a skip)
    std::string why;      // why not ok
    std::string implementation, device;
  };
  // Throws InputError when the worker found the options bad (a --device that does not exist).
  Opened opened();

  struct CaseRun {
    bool not_applicable = false;
    bool not_run = false;  // the row's worker could not be restarted after an earlier failure
    std::string failure;   // the line's text after the case's prefix; empty: compare `records`
    std::vector<PoiRecord> records;
    OpCounts counts;
    double seconds = 0;        // inside run()
    double build_seconds = 0;  // inside prepare(), before run()
  };
  // `index`: the case's number in the campaign; `reference_seconds`: ref-original's time on it.
  CaseRun run(const CheckCase& c, long index, double reference_seconds);

  // The backend's unsupported(p), asked in its worker (a case of no pairs): empty when it
  // supports p; a worker that is not running, or fails to answer, supports nothing.
  std::string unsupported(const Params& p);

  // Whether the row's worker answers that `p` is outside its limits: false when it supports `p`,
  // is not running or does not answer (its next run() then reports that).
  bool outside_limits(const Params& p);

  // The records of `pairs` (any size), for the reproducer's shrinking: the case's error, crash
  // or "n/a" as its `error`. Never restarts a worker.
  struct PairsRun {
    std::vector<PoiRecord> records;
    std::string error;
  };
  PairsRun run_pairs(std::span<const FramePair> pairs, const Params& p);

  // The allowance for `pairs` pairs of `p` whose reference time is `reference_seconds`.
  double allowance(const Params& p, std::size_t pairs, double reference_seconds) const;

 private:
  std::string locate_crash(const CheckCase& c, double reference_seconds, std::string& note);
  // The worker's prepare(p) within kPrepareSeconds; a worker that died or did not finish is
  // dropped (restarted by the next run()).
  worker::Reply prepare(const Params& p);
  // Builds the case's kernels; false when that ended the case (`out` says how).
  bool built(const Params& p, const std::string& which, CaseRun& out);
  bool restart(std::string& why);

  std::string row_;
  IsolationOptions options_;
  std::unique_ptr<worker::WorkerProcess> worker_;
  double worst_ratio_ = -1;  // the row's slowest seconds per reference second; < 0: none yet
  bool dead_ = false;
};

}  // namespace pxflow
