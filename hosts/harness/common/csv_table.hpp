// CSV as pxflow's files write it: a header line of the columns, then one line per JSON object,
// a string quoted (its quotes doubled), a number or a bool as JSON spells it, a key the object
// lacks an empty cell. The report's CSV files (report/report_csv.hpp) and compare.csv
// (bench/bench_compare.hpp) are made by it.
#pragma once
#include <string>
#include <vector>

#include "result_json.hpp"

namespace pxflow {

// The columns `cols` of each object `rows` points to, in the order given.
std::string csv_lines(const std::vector<std::string>& cols, const std::vector<const Json*>& rows);

// The columns `cols` of each object of the array `rows`, in its order.
std::string csv_table(const std::vector<std::string>& cols, const Json& rows);

}  // namespace pxflow
