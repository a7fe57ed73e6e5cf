// pxflow report: turns check, bench and accuracy results into report.md, a self-contained
// report.html (inline SVG charts), results.json (docs/report-schema.md: everything the page
// shows) and CSV files. Provenance comes first; every figure names its command and clock.
#pragma once
#include <map>
#include <nlohmann/json.hpp>  // complete: ReportInputs holds Json by value
#include <string>
#include <vector>

#include "bench_compare.hpp"
#include "output_plan.hpp"
#include "result_json.hpp"
#include "svg_chart.hpp"

namespace pxflow {

struct ReportInputs {
  Json check;  // check_json(), or null
  Json bench;  // bench_json(), or null
  // Every bench file given (report --bench-json A B ...), A (= bench) first: each has its own
  // provenance block; two or more are also compared with A. Empty when the report ran the bench.
  std::vector<BenchFile> bench_files;
  // What this run measured itself, on this machine ("check", "bench", "accuracy", a family
  // section's key): the only parts the local machine's provenance is shown for.
  std::vector<std::string> measured_here;
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

// The report's files in its folder, planned before any work.
struct ReportOutputs {
  std::string dir;
  std::map<std::string, OutputFile*> files;     // by file name: report_file_names() and more
  std::map<std::string, OutputFile*> pictures;  // by file name, written by the caller
  std::vector<std::string> previous;            // the files the folder's earlier report listed
};

// Plans the report's folder `out_dir` in `plan`: it must be missing (it is created), empty, or
// a previous pxflow report (it holds a .pxflow-report manifest); anything else is refused, so
// that a user's own files are never touched. `pictures`: the file names the caller may write.
ReportOutputs plan_report(OutputPlan& plan, const std::string& out_dir,
                          const std::vector<std::string>& pictures);

// Writes the report's files, then the manifest listing them and the pictures written; last, it
// removes the files the previous report listed that this one did not write, and only names this
// report can write (a hand-edited manifest cannot delete anything else).
void write_report(ReportOutputs& out, const ReportInputs& in);

// The manifest of a report a signal stopped: the previous report's files and `kept`, the files
// the stopped one wrote (its check), so that the folder stays the report's.
void write_stopped_manifest(ReportOutputs& out, const std::vector<std::string>& kept);

// Position of a backend in the registry (backend_rows()); names this build does not have (a
// results file of another build) come after every row. Every table and chart sorts by it.
std::size_t registry_rank(const std::string& backend);

}  // namespace pxflow
