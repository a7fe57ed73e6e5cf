// pxflow report: turns check and bench results into report.md, a self-contained report.html
// (inline SVG charts), results.json and results.csv. Every figure names its command and machine.
#pragma once
#include <string>

#include "result_json.hpp"

namespace pxflow {

struct ReportInputs {
  Json check;  // check_json(), or null
  Json bench;  // bench_json(), or null
  std::string check_command, bench_command, report_command;
};

// Writes the four files into out_dir (created if needed); throws InputError when it cannot.
void write_report(const std::string& out_dir, const ReportInputs& in);

}  // namespace pxflow
