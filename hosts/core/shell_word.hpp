// A word as a POSIX shell reads it back: as it is when nothing in it is special, else quoted.
// Every command line pxflow prints for a human to rerun goes through it.
#pragma once
#include <string>

namespace pxflow {

inline std::string shell_word(const std::string& s) {
  if (!s.empty() && s.find_first_of(" \t\n'\"\\$`*?;&|<>()[]{}!#~") == std::string::npos) return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace pxflow
