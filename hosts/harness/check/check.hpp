// pxflow check: every selected backend against ref-original, record by record and flow by bits,
// in the manner of checkasm: one line per mismatch, the run goes on, a count at the end.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "backend.hpp"
#include "check_campaign.hpp"
#include "check_corpus.hpp"
#include "check_repro.hpp"
#include "interrupt.hpp"
#include "isolated_row.hpp"
#include "result_fields.hpp"
#include "result_json.hpp"

namespace pxflow {

struct CheckReport;

struct CheckOptions {
  std::vector<std::string> backends;  // empty: every registered backend
  std::vector<std::string> require;   // skips of these become failures; "all": every selected
  long fuzz_pairs = 0;                // > 0: a fuzz campaign of that many random pairs instead
  Shard shard;                        // the part of the campaign to run (check_campaign.hpp)
  bool verbose = false;               // dump the 8x8 blocks behind each mismatch
  int max_lines_per_case = 5;
  BackendOptions backend_options;
  // Every row but the reference runs in a worker process (isolated_row.hpp): its command line
  // and the allowance of a case.
  IsolationOptions isolation;
  CorpusOptions corpus;
  ReproOptions repro;  // the reproducers of mismatches (check_repro.hpp); none without a writer
  // Printed once the backends are chosen and opened, so that bad input (an unknown or absent
  // backend, a device that does not exist) leaves no partial output.
  std::string banner;
  // What the results file records of the run: the command and the binary that ran it.
  std::string command, pxflow_version, pxflow_commit;
  std::string global_options;  // " --dut ...": recorded for `check --resume` (RunOptions)
  // A stopped run of this campaign (check_resume.hpp): this run goes on from its first case not
  // done, with its tallies and failure lines, as if it had never stopped.
  const CheckReport* resume = nullptr;
  std::string resume_file;  // its file, for messages
};

// How a backend came out of a check (JSON and reports spell it with state_name()).
// kReference: ref-original, whose records are the answer (never counted as checked).
// kIncomplete: only from `pxflow merge`: passed in every shard given, but shards are missing.
enum class BackendState { kPassed, kFailed, kSkipped, kReference, kIncomplete };
const char* state_name(BackendState s);  // "passed", "failed", "skipped", "reference", ...
BackendState state_from_name(const std::string& name);  // throws std::invalid_argument

struct BackendOutcome {
  std::string name;
  BackendState state = BackendState::kPassed;
  std::string reason;                  // why skipped
  std::string implementation, device;  // Backend::describe(), device_or_host(); empty: not opened
  long passed = 0, failed = 0, not_applicable = 0;  // cases
  long pairs = 0;
  double seconds = 0;                 // host time inside run()
  double build_seconds = 0;           // host time inside prepare(): building kernels, not run()
  std::vector<std::string> failures;  // the mismatch lines printed
  // The limit cases it ran, n/a ones not (check_limits.hpp: limit_entry()).
  std::vector<std::string> limits;
};

// What campaign a results file belongs to: shards merge only when all of it is equal.
struct CampaignInfo {
  std::string kind;     // "fixed-corpus" or "fuzz"
  long fuzz_pairs = 0;  // N of --cases; 0 for the fixed corpus
  bool generated_only = false;
  int corpus_version = kCheckCorpusVersion;
  std::string fingerprint;                     // Campaign::fingerprint()
  std::vector<std::string> settings;           // parameter settings of its cases
  std::vector<std::string> backends, require;  // as selected (every backend: the registry's)
  long cases = 0, pairs = 0;                   // of the whole campaign, every shard
  bool operator==(const CampaignInfo&) const = default;
};

// What shaped a single run beyond its campaign (the file's "options"): what `pxflow check
// --resume` runs the rest of a stopped campaign with.
struct RunOptions {
  std::string data_dir, device, global_options;
  bool limits_only = false;
  int threads = 0;
  double case_timeout = 0;  // --case-timeout; 0: the scaled allowance
  ParamOverride params;     // --profile, --set
  bool operator==(const RunOptions&) const = default;
};

// One shard's file in a merged result.
struct MergedShard {
  std::string file;
  Shard shard;
  CaseRange range;
  long pairs = 0;
  double seconds = 0;
};

struct CheckReport {
  std::uint64_t seed = 0;
  long cases = 0, pairs = 0;  // run here (this shard's, or every merged shard's)
  std::vector<BackendOutcome> backends;
  long passed = 0, failed = 0, skipped = 0, not_applicable = 0;
  long compared = 0;  // (backend, case) comparisons made, the reference's own not counted
  std::string command, pxflow_version, pxflow_commit;
  CampaignInfo campaign;
  Shard shard;         // of a single run; a merged result has merged_from instead
  CaseRange range;     // the cases of the campaign this run ran
  double seconds = 0;  // wall time of the run (merged: summed over the shards)
  std::vector<MergedShard> merged_from;
  std::vector<int> missing_shards;  // merged: the shards not given (incomplete)
  RunOptions options;               // of a single run
  // False when a signal stopped the run: it holds the cases [range.first, range.first + cases)
  // and `stop` says which signal (the command writes the file, then throws it).
  bool complete = true;
  std::optional<Interrupted> stop;

  // "incomplete" (a run stopped by a signal, whatever it found so far; a merge without every
  // shard when nothing failed), "failed" (something failed), "nothing-checked" (no backend but
  // the reference ran a case: a run of skips is not green) or "passed".
  std::string verdict() const;
  bool ok() const { return verdict() == "passed"; }
  // The cases this run was to check: its shard's (a merge: the whole campaign's).
  long cases_total() const { return merged_from.empty() ? range.size() : campaign.cases; }
};

// Runs the check, printing progress lines to `out` as it goes (and a live counter to stderr
// when stderr is a terminal). Throws InputError for unknown backend names.
CheckReport run_check(const CheckOptions& o, std::ostream& out);

// The results file (docs/harness.md, "The check file"), and back; check_from_json throws
// InputError naming the missing or mistyped key.
// The fields of both as the file and conformance.csv carry them (check_json.cpp): the only
// list of them.
std::span<const ResultField<CheckReport>> check_report_fields();
std::span<const ResultField<BackendOutcome>> backend_outcome_fields();
Json check_json(const CheckReport& r);
CheckReport check_from_json(const Json& j);

// The human summary after the mismatch lines: the table of backends (with the implementation
// and device that ran), the time taken, and the last line "N passed, M failed, K skipped".
void print_check_summary(const CheckReport& r, std::ostream& out);

// "shard 3/3 not given: its cases were not checked" (or "shards 2/3, 3/3 ... their"): what an
// incomplete merge of `count` shards lacks, said the same in merge's summary and the report.
std::string missing_shards_text(const std::vector<int>& missing, int count);

}  // namespace pxflow
