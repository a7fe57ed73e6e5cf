// pxflow compare: bench files of other builds, drivers or machines side by side (docs/harness.md,
// "Comparing bench files"). The first file is the baseline; a row of the others is compared only
// with the baseline's row of the same work (row_key: backend, clock, every parameter, batch,
// threads, device), never with a row that differs in any of it. Over the two rows' process
// medians: the ratio (Hodges-Lehmann) with its distribution-free 95 % interval and the
// Mann-Whitney U test; a gate (--fail-above PCT) fails a row only when the whole interval lies
// above 1 + PCT/100 and the test is significant, passes it only when the whole interval lies at or
// below, and otherwise calls it inconclusive.
#pragma once
#include <iosfwd>
#include <nlohmann/json.hpp>  // complete: BenchFile holds a Json by value
#include <span>
#include <string>
#include <vector>

#include "result_fields.hpp"
#include "result_json.hpp"

namespace pxflow {

// A change is significant when the U test's p-value is below this (compare.py's alpha).
inline constexpr double kSignificanceLevel = 0.05;

// pxflow compare's exit status when the gate could not decide (docs/harness.md): no row failed,
// and a row's interval held the threshold, or its files had too few processes or a disturbed
// machine.
inline constexpr int kInconclusiveExit = 3;

struct CompareOptions {
  bool across_machines = false;  // compare files of different machines (else an InputError)
  double fail_above = -1;        // the gate's percent; < 0: no gate
};

// One bench file (pxflow bench --json), as read: `label` "A", "B", ... in the order given.
struct BenchFile {
  std::string path, label;
  Json bench;
};

// "A" for the first file given, "B", ... "Z" (and "Z" for any beyond).
std::string file_label(std::size_t index);

// Checks that `j` is a bench file whose rows carry what the comparison reads; throws InputError
// ("PATH: ...") otherwise.
void check_bench_file(const std::string& path, const Json& j);

// "a.json: h (Intel ...), 4 cores; pxflow 0.9 at abc123, GNU 12.2.0; 2026-12-03 ...": what the
// file's provenance says of its machine and build ("?" where an older file lacks it).
std::string file_identity(const BenchFile& f);
std::string file_machine(const BenchFile& f);  // "h (Intel ...)", for a section's title

struct CompareRow {
  std::string file;  // the label of the file compared with the baseline
  std::string backend, sweep, setting, source;
  int width = 0, height = 0, search_radius = 0, batch = 0, threads = 0, base_threads = 0;
  int samples = 0, base_samples = 0, processes = 0, base_processes = 0;
  double base_median_ns = 0, median_ns = 0;
  // The row's time over the baseline's (> 1: slower): the Hodges-Lehmann estimate over the
  // process medians, and its 95 % interval (ratio_interval95); an exact clock's plain quotient.
  double ratio = 0, ratio_ci_low = 0, ratio_ci_high = 0;
  double p_value = -1;  // the U test's; -1: not tested (an exact clock: one deterministic count)
  // "slower", "faster", "not significant", or "inconclusive" (then `why`).
  std::string verdict;
  std::string gate;  // with --fail-above: "fail", "pass" or "inconclusive" (then `why`); else ""
  std::string why;
};

struct BenchComparison {
  std::vector<std::string> files;  // file_identity() of each, baseline first
  // "B was measured on a disturbed machine (...)": its changes may be the load, not the build.
  std::vector<std::string> warnings;
  std::vector<CompareRow> rows;
  // Rows that have no counterpart to compare with: "B: avx2 batch=1 (host-steady-clock): ..."
  // and rows whose baseline row differs in its work: "...: not comparable: blocks 8 in A, 2 here".
  std::vector<std::string> not_compared;
  std::string across_machines;  // "A and B were measured on different machines: ..." or empty
  double fail_above = -1;
};

// Every file after the first against the first (at least two files). Files of different machines
// are an InputError unless options.across_machines.
BenchComparison compare_bench_files(std::span<const BenchFile> files,
                                    const CompareOptions& options = {});

// pxflow compare's exit status: 1 when nothing was compared or a row failed the gate; else
// kInconclusiveExit when a row's gate was inconclusive; else 0.
int comparison_exit(const BenchComparison& c);

// A compare row's fields as compare.json and compare.csv carry them: the only list of them.
std::span<const ResultField<CompareRow>> compare_row_fields();
Json comparison_json(const BenchComparison& c);
std::string comparison_csv(const BenchComparison& c);

// "backend  point  clock  A ns/frame  B ns/frame  B/A [95% CI]  p  verdict" lines.
void print_comparison(const BenchComparison& c, std::ostream& out);

// "1.204 [1.18, 1.23]" and "batch=256 640x480 S=4 threads=2": one spelling for table and report.
std::string ratio_text(const CompareRow& r);
std::string point_text(const CompareRow& r);

}  // namespace pxflow
