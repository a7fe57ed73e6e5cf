// How the report's sections read a bench row of results.json (bench_row_fields()): its clock,
// whether it was timed, and the cells every table writes the same way.
#pragma once
#include <string>
#include <vector>

#include "result_json.hpp"
#include "svg_chart.hpp"

namespace pxflow::report {

std::string num(double v, const char* format = "%.1f");
// The string at `key`, or "" when there is none.
std::string str(const Json& j, const char* key);

bool timed(const Json& row);
bool host_clock(const Json& row);
// A deterministic device clock (the GAP8 model's cycles): one checked run is the measurement.
bool exact_clock(const Json& row);
// An exact clock that counts instructions, not cycles (QEMU -icount: the m4-qemu row). Its
// frames/s assume one instruction per tick of QEMU's virtual clock, a speed no core has: it is
// tabled, labelled as such, and never charted beside the cycle models.
// Such a backend shows its instructions per frame, never a time or a rate: its untimed rows (n/a,
// not run) belong to the same one line.
bool counts_instructions(const Json& row);
bool counts_instructions(const Json& bench, const std::string& backend);
std::string instructions_cell(const Json& row);
// A row's bound per frame with its unit ("1603 tsc cycles", "91136 instr"), and the fraction of
// it the row achieved ("11.7 %"; "none" for a timed row without one, whose note says why; "-"
// for a row of a file written before every row had its bound).
std::string bound_cell(const Json& row);
std::string fraction_cell(const Json& row);
// Said under a table with rows labelled by an instruction count.
extern const char* const kInstructionNote;

std::string threads_text(int n);  // "1 thread", "4 threads"
// "a signal stopped this bench after N of M points" for a bench a signal stopped ("complete":
// false), "" for a whole one.
std::string stopped_after(const Json& bench);
// "px4flow-64, 64x64, S=4, batch 256, 2 threads": a row's point.
std::string point_name(const Json& row);
// The elements of `rows` (bench rows, described backends) sorted by their backend's registry
// position, stable within a backend (the file's order).
std::vector<const Json*> in_registry_order(const Json& rows);
// A backend's style in every chart: its registry position's.
ChartStyle style_of(const std::string& backend);

}  // namespace pxflow::report
