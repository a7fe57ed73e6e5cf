// "1 pair", "2 pairs": a count with its noun, singular for exactly one. The one place pxflow makes
// a plural, so that no message says "1 threads" or "1 points".
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace pxflow {

// `plural` defaults to `singular` + "s"; give it for the irregular ones ("1 case", "2 cases" need
// none; "1 process", "2 processes" do).
inline std::string counted(long long n, std::string_view singular, std::string_view plural = {}) {
  std::string s = std::to_string(n) + " ";
  if (n == 1) return s.append(singular);
  return plural.empty() ? s.append(singular).append("s") : s.append(plural);
}

// 92032 -> "92,032": a large count as docs and messages write it.
inline std::string grouped(std::uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace pxflow
