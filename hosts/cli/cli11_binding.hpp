// The one door to the parser: pxflow's declarations (option_spec.hpp) become CLI11's options in
// cli11_binding.cpp, the only file that includes CLI11, so that no command pays its compile time.
#pragma once
#include <functional>
#include <optional>
#include <string>

#include "option_spec.hpp"

namespace pxflow::cli {

struct ParseOutcome {
  std::optional<int> exit_code;  // --help or --version printed: exit with this
  std::string error;             // the parser's error ("--cases: Value 0 not in range 1 to 9")
};

// Parses argv[1..] against `top` (its options the global ones, its subcommands the commands,
// one of which must be given; global options may follow the command). On success, every
// option's `results` and every command's `parsed` are filled, and the targets hold the values.
ParseOutcome parse_command_line(CommandSpec& top, const std::function<std::string()>& version,
                                int argc, char** argv);

}  // namespace pxflow::cli
