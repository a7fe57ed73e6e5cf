// What a backend family adds to the command line beside its rows: a command of its own and a
// section of `pxflow report`. Registered by the family's pxflow_backend_family() call
// (CLI_EXTENSION); the CLI iterates registered_cli_extensions() and knows no family by name.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "commands.hpp"

namespace pxflow {
struct ReportInputs;  // report.hpp, included by the files that add a section
}  // namespace pxflow

namespace pxflow::cli {

struct CliExtension {
  std::string family;                                // the BackendFamily name it belongs to
  std::function<Command(CommandSpec&)> add_command;  // e.g. `pxflow gap8`; empty: none
  // The report section, added when the report's backends include a row of `family` and the
  // user did not pass `report_skip_flag`. It appends to in.sections.
  std::string report_skip_flag, report_skip_help;  // e.g. "--no-gap8"
  std::function<void(ReportInputs& in)> add_report_section;
};

std::vector<CliExtension> registered_cli_extensions();  // generated (cmake/)

}  // namespace pxflow::cli
