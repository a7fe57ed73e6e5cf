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
  // Sections a family adds (the GAP8 model beside the paper's tables), after the harness's own:
  // tables with optional inline SVG charts, the command that measured them, and their raw
  // figures for results.json under `key`.
  struct Table {
    std::string title, text;
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    std::string svg;
  };
  struct Section {
    std::string key;      // results.json key, e.g. "gap8"
    std::string command;  // e.g. "pxflow gap8 --cores 1-8"
    std::vector<Table> tables;
    Json data;  // raw figures, or null
  };
  std::vector<Section> sections;
};

// Creates out_dir if needed (InputError when it cannot): called before any work.
void prepare_report_dir(const std::string& out_dir);

// Removes the files a previous report wrote into out_dir, as its manifest (.pxflow-report) lists
// them, and nothing else: called after all the work, just before the new files are written, so
// that an interrupted or failed run leaves the previous report intact.
void remove_previous_report(const std::string& out_dir);

// Writes the four files into out_dir, then the manifest listing them and the pictures.
void write_report(const std::string& out_dir, const ReportInputs& in);

}  // namespace pxflow
