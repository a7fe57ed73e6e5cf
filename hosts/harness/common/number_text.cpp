#include "number_text.hpp"

#include <cstdio>

namespace pxflow {

std::string formatted(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

}  // namespace pxflow
