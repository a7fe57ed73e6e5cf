#include "real_options.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace pxflow::cli {
namespace {

std::string real_text(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

}  // namespace

std::string real_value_problem(const std::string& text, double lo, double hi) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  // CLI11's Range wording, which parse_errors.cpp turns into pxflow's one line.
  if (text.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi)
    return "Value " + text + " not in range " + real_text(lo) + " to " + real_text(hi);
  return "";
}

std::string real_value_name(double lo, double hi) {
  return "FLOAT in [" + real_text(lo) + " - " + real_text(hi) + "]";
}

}  // namespace pxflow::cli
