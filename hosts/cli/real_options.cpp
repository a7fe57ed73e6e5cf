#include "real_options.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace pxflow::cli {
namespace {

std::map<const CLI::Option*, std::pair<double, double>>& declared_reals() {
  static std::map<const CLI::Option*, std::pair<double, double>> table;
  return table;
}

std::string real_text(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

}  // namespace

CLI::Option* declare_real(CLI::Option* option, double lo, double hi) {
  declared_reals()[option] = {lo, hi};
  option->check(CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        // CLI11's Range wording, which parse_errors.cpp turns into pxflow's one line.
        if (text.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi)
          return "Value " + text + " not in range " + real_text(lo) + " to " + real_text(hi);
        return "";
      },
      "FLOAT in [" + real_text(lo) + " - " + real_text(hi) + "]"));
  return option;
}

std::optional<std::pair<double, double>> declared_real(const CLI::Option* option) {
  const auto it = declared_reals().find(option);
  if (it == declared_reals().end()) return std::nullopt;
  return it->second;
}

}  // namespace pxflow::cli
