// pxflow backends: the registry as a table: name, whether it can run here (or why not), needs.
#include <cstdio>

#include "commands.hpp"
#include "registry.hpp"

namespace pxflow::cli {

Command add_backends_command(CLI::App& app) {
  CLI::App* sub =
      app.add_subcommand("backends", "List the compiled backends and whether each can run here");
  return {sub, [] {
            std::printf("%-14s %-10s %s\n", "backend", "status", "needs / reason");
            for (const auto& row : backend_rows()) {
              const std::string why = row.probe();
              std::printf("%-14s %-10s %s\n", row.name.c_str(),
                          why.empty() ? "available" : "skipped",
                          why.empty() ? row.needs.c_str() : why.c_str());
            }
            return 0;
          }};
}

}  // namespace pxflow::cli
