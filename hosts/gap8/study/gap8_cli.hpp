// The GAP8 family's part of the command line (gap8_cli.cpp registers it): `pxflow gap8` and the
// report's section with the kernel's variants at 1..8 cores beside the ISCAS 2022 paper's
// Tables I-III.
#pragma once
#include "commands.hpp"

namespace pxflow {
struct ReportInputs;  // report.hpp
}  // namespace pxflow

namespace pxflow::cli {

Command add_gap8_command(CommandSpec& app);  // gap8_command.cpp

// Runs `pxflow gap8 --cores 1-8` and appends its section: tables, a speed-up chart and the raw
// figures. When the default frame pair cannot be loaded, the section says why instead.
void add_gap8_tables(ReportInputs& in);  // report_gap8.cpp

}  // namespace pxflow::cli
