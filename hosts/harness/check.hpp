// pxflow check: every selected backend against ref-original, record by record and flow by bits,
// in the manner of checkasm: one line per mismatch, the run goes on, a count at the end.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "backend.hpp"
#include "check_corpus.hpp"
#include "result_json.hpp"

namespace pxflow {

struct CheckOptions {
  std::vector<std::string> backends;  // empty: every registered backend
  std::vector<std::string> require;   // skips of these become failures; "all": every selected
  long fuzz_pairs = 0;                // > 0: a fuzz campaign of that many random pairs instead
  bool verbose = false;               // dump the 8x8 blocks behind each mismatch
  int max_lines_per_case = 5;
  BackendOptions backend_options;
  CorpusOptions corpus;
  // Printed once the backends are chosen and opened, so that bad input (an unknown or absent
  // backend, a device that does not exist) leaves no partial output.
  std::string banner;
};

// How a backend came out of a check (JSON and reports spell it with state_name()).
// kReference: ref-original, whose records are the answer (never counted as checked).
enum class BackendState { kPassed, kFailed, kSkipped, kReference };
const char* state_name(BackendState s);  // "passed", "failed", "skipped", "reference"

struct BackendOutcome {
  std::string name;
  BackendState state = BackendState::kPassed;
  std::string reason;                               // why skipped
  long passed = 0, failed = 0, not_applicable = 0;  // cases
  long pairs = 0;
  double seconds = 0;                 // host time inside run()
  std::vector<std::string> failures;  // the mismatch lines printed
};

struct CheckReport {
  std::uint64_t seed = 0;
  long cases = 0, pairs = 0;
  std::vector<BackendOutcome> backends;
  long passed = 0, failed = 0, skipped = 0, not_applicable = 0;
  long compared = 0;  // (backend, case) comparisons made, the reference's own not counted
  // A check passes when nothing failed and something was compared: a run in which every
  // backend was skipped or n/a tested nothing and is not green.
  bool ok() const { return failed == 0 && compared > 0; }
};

// Runs the check, printing progress lines to `out` as it goes (and a live counter to stderr
// when stderr is a terminal). Throws InputError for unknown backend names.
CheckReport run_check(const CheckOptions& o, std::ostream& out);

Json check_json(const CheckReport& r);

}  // namespace pxflow
