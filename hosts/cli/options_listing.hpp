// `pxflow --list-options`: every command's options as JSON, from their declarations
// (option_spec.hpp), with the path kind of each (path_options.hpp) and the command's matrix runs,
// for the generated tests (tests/cli).
#pragma once
#include <string>
#include <vector>

#include "commands.hpp"

namespace pxflow::cli {

std::string list_options_json(const CommandSpec& app, const std::vector<Command>& commands);

}  // namespace pxflow::cli
