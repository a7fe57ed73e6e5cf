// pxflow backends: the registry as a table (name, whether it can run here or why not, needs), or
// as JSON with the family of each row.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "json_document.hpp"
#include "output_plan.hpp"
#include "registry.hpp"

namespace pxflow::cli {
namespace {

int run_backends(const std::string& json_path) {
  OutputPlan plan;
  OutputFile* const json_file = json_path.empty() ? nullptr : &plan.file("--json", json_path);
  plan.prepare();
  Json rows = Json::array();
  const bool table = json_path != kStdoutPath;
  if (table) std::printf("%-14s %-10s %s\n", "backend", "status", "needs / reason");
  for (const auto& row : backend_rows()) {
    const std::string why = row.probe();
    if (table)
      std::printf("%-14s %-10s %s\n", row.name.c_str(), why.empty() ? "available" : "skipped",
                  why.empty() ? row.needs.c_str() : why.c_str());
    rows.push_back({{"backend", row.name},
                    {"family", row.family},
                    {"available", why.empty()},
                    {"reason", why},
                    {"needs", row.needs},
                    {"has_devices", row.has_devices},
                    {"preferred", row.preferred}});
  }
  if (json_file) json_file->write(json_document(Json{{"backends", rows}}));
  return 0;
}

}  // namespace

const std::vector<std::string> kBackendsExamples = {
    "backends  # what this build has, and what can run here",
    "backends --json -  # the same as JSON",
};

Command add_backends_command(CommandSpec& app) {
  auto json_path = std::make_shared<std::string>();
  CommandSpec* sub =
      &app.add_subcommand("backends", "List the compiled backends and whether each can run here");
  add_json_option(*sub, *json_path,
                  "the rows: name, family, available, reason, needs, has_devices, preferred; "
                  "with '-' instead of the table");
  return {sub, [json_path] { return run_backends(*json_path); }, kBackendsExamples, {""}};
}

}  // namespace pxflow::cli
