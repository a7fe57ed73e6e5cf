// The report's sections, built from the results once and rendered three ways (Markdown, HTML,
// results.json) by report.cpp, so that the files cannot disagree.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "bench_compare.hpp"
#include "report.hpp"
#include "svg_chart.hpp"

namespace pxflow::report {

struct Section {
  std::string key;  // stable name in results.json ("provenance", "throughput", "scaling-batch")
  std::string title, text;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<Chart> charts;
  std::vector<ReportInputs::Picture> pictures;
};

// The report's own provenance (report_provenance.cpp): pxflow's build, this machine for what the
// report measured itself (ReportInputs::measured_here) and the commands run.
Section provenance(const ReportInputs& in, const Json& build, const Json& machine);
// One block per bench file, from the file's own provenance (build, machine, load, whether a
// signal stopped it), never this machine's; `backends_shown`: its backends are the backends
// section's, else they are listed here. As results.json's provenance.bench_files carries them.
Section bench_file_provenance(const BenchFile& f, bool backends_shown);
Json bench_files_json(std::span<const BenchFile> files);
// Whether the report holds figures of more than one machine: the bench files' and, when the
// report measured anything itself, this one (`machine`). Then every bench section names its
// file's machine.
bool several_machines(const ReportInputs& in, const Json& machine);

// Which machine a bench's sections show, for a report of several: "A: host (CPU)" in titles,
// "host (CPU)" after each series; both empty in a report of one machine.
struct MachineTag {
  std::string title, series;
};
Section backends_section(const ReportInputs& in);
Section conformance(const Json& check, const std::string& command);
// The headline point of the bench: every backend, host clock and exact model clock apart.
Section throughput(const Json& bench, const std::string& command, const MachineTag& tag);
// One sweep ("batch", "size", "radius", "threads") as a table and charts.
Section scaling(const Json& bench, const std::string& sweep, const MachineTag& tag);
// The points of a bench's own sweep (bench --batch, --sizes, --radius, --thread-sweep: rows of
// sweep "custom"), every one: a table and a chart over the one parameter that varies, or a
// table of every point when several vary; none when the bench measured one point.
std::vector<Section> custom_points(const Json& bench, const MachineTag& tag);
bool has_sweep(const Json& bench, const std::string& sweep);
// Every timed row's bound and the fraction of it achieved: a table, and a chart per point
// (report_bound.cpp).
Section bound_section(const Json& bench, const MachineTag& tag);
Section accuracy(const ReportInputs& in);
// Several bench files (report_compare.cpp): one chart across them and the files' identities,
// then a section per file compared with the first.
// `several_machines`: each series names its file's machine.
std::vector<Section> comparison_sections(std::span<const BenchFile> files, const BenchComparison& c,
                                         bool several_machines);

// The chart as results.json carries it (docs/report-schema.md).
Json chart_json(const Chart& c);

}  // namespace pxflow::report
