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

}  // namespace pxflow::cli
