// A number as one printf conversion spells it: formatted("%.3f", 1.2) is "1.200". The bench's
// table, pxflow compare's and the report's charts share it, and the bound's cell of both tables.
#pragma once
#include <string>

namespace pxflow {

// `format` holds one conversion of a double ("%.1f", "%8.2f", "%g"); at most 63 characters come
// out.
std::string formatted(const char* format, double v);

// A bound per frame with its unit as the bench's table and the report both show it: `unit` is
// the JSON's `bound_unit` ("tsc-cycles", "cycles", "instructions", "ns"), e.g. "5003 tsc cycles".
std::string bound_text(double per_frame, const std::string& unit);

}  // namespace pxflow
