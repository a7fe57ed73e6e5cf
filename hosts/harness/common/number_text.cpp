#include "number_text.hpp"

#include <cstdio>

namespace pxflow {

std::string formatted(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

std::string bound_text(double per_frame, const std::string& unit) {
  const char* suffix = unit == "instructions" ? " instr"
                       : unit == "ns"         ? " ns"
                       : unit == "tsc-cycles" ? " tsc cycles"
                                              : " cycles";
  return formatted(per_frame < 100 ? "%.1f" : "%.0f", per_frame) + suffix;
}

}  // namespace pxflow
