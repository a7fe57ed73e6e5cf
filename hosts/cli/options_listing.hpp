// `pxflow --list-options`: every command's options as JSON, with the path kind of each
// (path_options.hpp) and the command's matrix runs, for the generated tests (tests/cli).
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "commands.hpp"

namespace pxflow::cli {

std::string list_options_json(const CLI::App& app, const std::vector<Command>& commands);

}  // namespace pxflow::cli
