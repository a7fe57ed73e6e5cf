// A number as one printf conversion spells it: formatted("%.3f", 1.2) is "1.200". The bench's
// table, pxflow compare's and the report's charts share it.
#pragma once
#include <string>

namespace pxflow {

// `format` holds one conversion of a double ("%.1f", "%8.2f", "%g"); at most 63 characters come
// out.
std::string formatted(const char* format, double v);

}  // namespace pxflow
