// Comma-separated list options ("a,b,c") shared by the harness commands.
#pragma once
#include <string>
#include <vector>

#include "option_spec.hpp"

namespace pxflow::cli {

inline std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::string item;
  for (char ch : text + ",") {
    if (ch != ',') {
      item += ch;
    } else if (!item.empty()) {
      out.push_back(item);
      item.clear();
    }
  }
  return out;
}

// For a list option: given, it must name at least one item (`--batch ""` is an error, not the
// default sweep).
inline ValueCheck non_empty_list() {
  return {[](const std::string& s) {
            return split_list(s).empty() ? std::string("needs at least one value") : std::string();
          },
          "LIST"};
}

// A seed: a decimal number from 0 to 2^64-1 (CLI11 would read -1 as 2^64-1 and clamp larger
// numbers to it).
inline ValueCheck seed_value() {
  return {[](const std::string& s) {
            const bool digits =
                !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
            if (!digits || s.size() > 20 || (s.size() == 20 && s > "18446744073709551615"))
              return std::string("must be a whole number from 0 to 18446744073709551615, not '" +
                                 s + "'");
            return std::string();
          },
          "SEED"};
}

}  // namespace pxflow::cli
