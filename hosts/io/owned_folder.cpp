#include "owned_folder.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "errors.hpp"
#include "output_plan.hpp"
#include "system_files.hpp"

namespace pxflow {
namespace fs = std::filesystem;

void check_owned_folder(const std::string& option, const std::string& dir,
                        const std::string& manifest) {
  std::error_code ec;
  if (!fs::exists(dir, ec) || fs::is_regular_file(fs::path(dir) / manifest, ec)) return;
  if (!fs::is_directory(dir, ec)) return;  // a file: OutputPlan::prepare names it
  // Empty, or holding nothing but pxflow's own temporaries (a run killed before its manifest:
  // its leftovers never block the next run, which removes them).
  bool others = false;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    others |= !is_pxflow_temporary(entry.path().filename().string());
  if (!others && !ec) return;
  throw InputError(option + " " + dir + ": holds files and no earlier pxflow output (" + manifest +
                   "); give a new or empty folder, so that no file of yours is replaced");
}

std::vector<std::string> manifest_names(const std::string& dir, const std::string& manifest) {
  std::istringstream text(read_own_output((fs::path(dir) / manifest).string()));
  std::vector<std::string> names;
  for (std::string name; std::getline(text, name);)
    if (!name.empty()) names.push_back(name);
  return names;
}

std::string manifest_text(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += name + "\n";
  return text;
}

void remove_unwritten(const std::string& dir, const std::vector<std::string>& previous,
                      const std::vector<std::string>& may_write,
                      const std::vector<std::string>& written) {
  auto among = [](const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  for (const std::string& name : previous) {
    if (!among(may_write, name) || among(written, name)) continue;
    std::error_code ec;
    const fs::path f = fs::path(dir) / name;
    if (fs::is_regular_file(fs::symlink_status(f, ec))) fs::remove(f, ec);
  }
}

}  // namespace pxflow
