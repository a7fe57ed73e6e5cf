// pxflow report: turns check, bench and accuracy results into report.md, a self-contained
// report.html (inline SVG charts), results.json (docs/report-schema.md: everything the page
// shows) and CSV files. Provenance comes first; every figure names its command and clock.
#pragma once
#include <string>
#include <vector>

#include "result_json.hpp"
#include "svg_chart.hpp"

namespace pxflow {

struct ReportInputs {
  Json check;  // check_json(), or null
  Json bench;  // bench_json(), or null
  std::string check_command, bench_command, report_command;
  // What each backend runs (provenance.hpp: describe_backend), in registry order, and where the
  // descriptions come from (the bench's run, or this report opening the rows).
  Json backends = Json::array();
  std::string backends_source;
  // Accuracy against ground truth and OpenCV: header row first; empty when not run. The same
  // figures as numbers, one object per row, for results.json.
  std::vector<std::vector<std::string>> accuracy;
  Json accuracy_rows = Json::array();
  std::string accuracy_command;
  // Flow pictures already written into the output folder (file name relative to it).
  struct Picture {
    std::string caption, file;
  };
  std::vector<Picture> pictures;
  // Sections a family adds (the GAP8 model beside the paper's tables), after the harness's own:
  // tables with optional charts, the command that measured them, and their raw figures for
  // results.json under `key`.
  struct Table {
    std::string title, text;
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    std::vector<Chart> charts;
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

// The files write_report() writes (the pictures aside), for the manifest and the --out checks.
const std::vector<std::string>& report_file_names();

// Writes the report's files into out_dir, then the manifest listing them and the pictures.
void write_report(const std::string& out_dir, const ReportInputs& in);

// Position of a backend in the registry (backend_rows()); names this build does not have (a
// results file of another build) come after every row. Every table and chart sorts by it.
std::size_t registry_rank(const std::string& backend);

}  // namespace pxflow
