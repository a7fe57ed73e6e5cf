#include "own_files.hpp"

namespace pxflow {

namespace fs = std::filesystem;

OwnFile find_own_file(const std::string& file, const std::vector<std::string>& reldirs) {
  OwnFile result;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return result;
  for (const std::string& rel : reldirs) {
    const fs::path path = (exe.parent_path() / rel / file).lexically_normal();
    bool seen = false;
    for (const fs::path& p : result.tried) seen = seen || p == path;
    if (seen) continue;
    result.tried.push_back(path);
    if (fs::is_regular_file(path, ec)) {
      result.found = path;
      break;
    }
  }
  return result;
}

std::string describe_tried(const std::vector<fs::path>& tried) {
  std::string text;
  for (std::size_t i = 0; i < tried.size(); ++i)
    text += (i == 0 ? "" : i + 1 == tried.size() ? " or " : ", ") + tried[i].string();
  return text;
}

}  // namespace pxflow
