// The parser's (CLI11's) errors in pxflow's one style: "<option>: <bad value>: <what is allowed>",
// followed by where to read more ("see pxflow CMD --help"), instead of CLI11's own sentences ("At
// Most 1 required but received 2", "Value 1e3 not in range 1 to 100000000").
#pragma once
#include <string>
#include <vector>

#include "option_spec.hpp"

namespace pxflow::cli {

// The error line (without "pxflow: error: ") for the parser's error `what`, raised while parsing
// `command` (empty: the top level).
std::string describe_parse_error(const std::string& what, const std::string& command);

// "unknown option --case (did you mean --cases?)" for the first --NAME of `args` (the words after
// the program's name) that neither `command` (with its own subcommands) nor `app` declares; "" if
// every --NAME is known. CLI11 takes a misspelt option's value for a stray argument
// (`--case 5`: "'5' not expected"), so a failed parse is first searched for such a name.
std::string unknown_option(const std::vector<std::string>& args, const CommandSpec& app,
                           const CommandSpec* command);

// Whether `app` (the top level) declares `name`: a global option, --help (-h) or --version.
bool declares_global(const CommandSpec& app, const std::string& name);

// " (did you mean --cases?)" when one of `app`'s visible options is within two edits of `name`.
std::string nearest_option(const std::string& name, const CommandSpec& app);

}  // namespace pxflow::cli
