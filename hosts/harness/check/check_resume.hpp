// `pxflow check --resume FILE`: a check a signal stopped (its --json file, "complete": false)
// finished from its first case not done, with the campaign, options and build it started with,
// so that the result is the uninterrupted run's: the same verdict, counts and failure lines
// (docs/harness.md, "Stopping and resuming a campaign"). run_check (check.hpp, `resume`) takes
// the stopped run over; these are its refusals, each one line starting with the option and file.
#pragma once
#include <string>

#include "check.hpp"

namespace pxflow {

// Throws InputError unless `r` is a stopped single run this build can finish: not a complete
// file, not a merge, with its options, written by this pxflow version and commit.
void check_resumable(const std::string& label, const CheckReport& r, const std::string& version,
                     const std::string& commit);

// Throws InputError naming the first difference between the campaign a resumed run is about to
// run (`now`: its campaign, shard and range) and the stopped run's.
void check_same_campaign(const std::string& label, const CheckReport& before,
                         const CheckReport& now);

// Throws InputError when a backend opens now but did not before, or the reverse, or opens to
// another implementation or device: its cases so far and the rest would not be one backend's.
void check_same_backend(const std::string& label, const BackendOutcome& before,
                        const BackendOutcome& now, bool opened_now);

// The stopped run's failures that no backend's tally holds (ref-original's own counts).
long reference_count_failures(const CheckReport& before);

}  // namespace pxflow
