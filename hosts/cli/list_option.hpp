// Comma-separated list options ("a,b,c") shared by the harness commands.
#pragma once
#include <string>
#include <vector>

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

}  // namespace pxflow::cli
