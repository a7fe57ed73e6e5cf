#include "file_inputs.hpp"

#include <algorithm>

namespace pxflow {
namespace {

std::vector<std::string>& inputs() {
  static std::vector<std::string> all;
  return all;
}

std::vector<std::pair<std::string, std::string>>& folders() {
  static std::vector<std::pair<std::string, std::string>> all;
  return all;
}

}  // namespace

void note_input(const std::string& path) {
  if (path.empty() || path == "-") return;
  auto& all = inputs();
  if (std::find(all.begin(), all.end(), path) == all.end()) all.push_back(path);
}

void note_input_folder(const std::string& option, const std::string& dir) {
  if (dir.empty()) return;
  auto& all = folders();
  const std::pair<std::string, std::string> entry{option, dir};
  if (std::find(all.begin(), all.end(), entry) == all.end()) all.push_back(entry);
}

const std::vector<std::string>& inputs_noted() { return inputs(); }

const std::vector<std::pair<std::string, std::string>>& input_folders_noted() { return folders(); }

}  // namespace pxflow
