// CLI11's parse errors in pxflow's one style: "<option>: <bad value>: <what is allowed>", followed
// by where to read more ("see pxflow CMD --help"), instead of CLI11's own sentences ("At Most 1
// required but received 2", "Value 1e3 not in range 1 to 100000000").
#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace pxflow::cli {

// The error line (without "pxflow: error: ") for `e`, raised while parsing `command` (empty:
// the top level).
std::string describe_parse_error(const CLI::ParseError& e, const std::string& command);

// "unknown option --case (did you mean --cases?)" for the first --NAME of `args` (the words after
// the program's name) that neither `command` (with its own subcommands) nor `app` declares; "" if
// every --NAME is known. CLI11 takes a misspelt option's value for a stray argument
// (`--case 5`: "'5' not expected"), so a failed parse is first searched for such a name.
std::string unknown_option(const std::vector<std::string>& args, const CLI::App& app,
                           const CLI::App* command);

// " (did you mean --cases?)" when one of `app`'s visible options is within two edits of `name`.
std::string nearest_option(const std::string& name, const CLI::App& app);

}  // namespace pxflow::cli
