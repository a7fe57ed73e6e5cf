// The report's sections, built from the results once and rendered three ways (Markdown, HTML,
// results.json) by report.cpp, so that the files cannot disagree.
#pragma once
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

// pxflow's build, the machine and the commands run; then what each backend runs.
Section provenance(const ReportInputs& in, const Json& build, const Json& machine);
Section backends_section(const ReportInputs& in);
Section conformance(const Json& check, const std::string& command);
// The headline point of the bench: every backend, host clock and exact model clock apart.
Section throughput(const Json& bench, const std::string& command);
// One sweep ("batch", "size", "radius", "threads") as a table and charts.
Section scaling(const Json& bench, const std::string& sweep);
Section accuracy(const ReportInputs& in);
// Several bench files (report_compare.cpp): one chart across them and the files' identities,
// then a section per file compared with the first.
std::vector<Section> comparison_sections(std::span<const BenchFile> files,
                                         const BenchComparison& c);

// The chart as results.json carries it (docs/report-schema.md).
Json chart_json(const Chart& c);

}  // namespace pxflow::report
