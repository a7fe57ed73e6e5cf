// The report's CSV files: results.csv (bench rows), conformance.csv (check backends) and
// accuracy.csv, one line per object of results.json, registry order. The bench's and the check's
// columns are their field tables' (bench_row_fields(), backend_outcome_fields()).
#pragma once
#include <string>

#include "result_json.hpp"

namespace pxflow {

// Each takes the object results.json carries (null: the part is not in the report, and the
// file is the header line alone); a key a row lacks is an empty cell.
std::string bench_csv(const Json& bench);
std::string conformance_csv(const Json& check);
std::string accuracy_csv(const Json& accuracy_rows);

}  // namespace pxflow
