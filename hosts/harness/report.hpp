// pxflow report: turns check and bench results into report.md, a self-contained report.html
// (inline SVG charts), results.json and results.csv. Every figure names its command and machine.
#pragma once
#include <string>
#include <vector>

#include "result_json.hpp"

namespace pxflow {

struct ReportInputs {
  Json check;  // check_json(), or null
  Json bench;  // bench_json(), or null
  std::string check_command, bench_command, report_command;
  // Accuracy against ground truth and OpenCV: header row first; empty when not run.
  std::vector<std::vector<std::string>> accuracy;
  std::string accuracy_command;
  // Flow pictures already written into the output folder (file name relative to it).
  struct Picture {
    std::string caption, file;
  };
  std::vector<Picture> pictures;
  // Sections measured outside the harness (the GAP8 model beside the paper's tables): a table
  // each, with an optional inline SVG chart, after the harness's own sections.
  struct Table {
    std::string title, text;
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    std::string svg;
  };
  std::vector<Table> tables;
  Json gap8;  // the GAP8 model's raw figures for results.json (pxflow gap8 --json), or null
  std::string gap8_command;
};

// Writes the four files into out_dir (created if needed); throws InputError when it cannot.
void write_report(const std::string& out_dir, const ReportInputs& in);

}  // namespace pxflow
