// The GAP8 part of pxflow report (only in builds with the GAP8 backends): the three kernel
// variants on the cluster model at 1..8 cores, beside the ISCAS 2022 paper's Tables I-III.
#pragma once
#include "report.hpp"

namespace pxflow::cli {

// Runs `pxflow gap8 --cores 1-8` and appends its tables, a speed-up chart and the raw figures.
// When the default frame pair cannot be loaded, the section says why instead.
void add_gap8_tables(ReportInputs& in);

}  // namespace pxflow::cli
