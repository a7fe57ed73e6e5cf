// A bench in separate processes (docs/harness.md, "Statistics"): the samples inside one process
// are not independent of the process (its clock frequency, placement, cache and page layout), so
// a point's interval and every test are over several processes' medians. `bench --processes R`
// runs its own binary R times; `compare --run OLD NEW` runs two binaries alternately. Each
// process is a plain `pxflow bench ... --processes 1 --json -`: any build since this one can be
// one side of a comparison.
#pragma once
#include <iosfwd>
#include <nlohmann/json.hpp>  // complete: BenchProcess holds a Json by value
#include <span>
#include <string>
#include <vector>

#include "bench.hpp"
#include "result_json.hpp"

namespace pxflow {

// What one bench process gave: its exit status (128 + N: killed by signal N), its --json output
// (null when it wrote none or not JSON), and its standard error's last line.
struct BenchProcess {
  int status = 0;
  Json bench;
  std::string last_error_line;
};

// Runs `argv` (a bench command line ending in `--json -`), its standard error kept from the
// terminal. A signal to pxflow stops the process and throws Interrupted.
BenchProcess run_bench_process(const std::vector<std::string>& argv);

// A bench file's JSON as a report again (rows, skipped, backends, machine, bound, provenance);
// throws nlohmann's exception when it is not one.
BenchReport bench_report_from_json(const Json& j);

// The reports of one bench's processes, each the same points, as one: every timed row's samples
// of every process, `samples_per_process` of each, its median the median of the processes'
// medians and its interval theirs (median_ci95); a row of an exact clock (a deterministic
// count) from the first process alone. The machine's shares are the processes', weighted by the
// seconds each measured; the provenance is the first process's.
BenchReport combine_processes(std::span<const BenchReport> runs);

// The rows of `r`, point by point, as the bench prints them.
void print_bench_rows(const BenchReport& r, std::ostream& out);

}  // namespace pxflow
