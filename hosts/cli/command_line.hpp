// The command line a subcommand actually ran, rebuilt from what was parsed (global options,
// then the subcommand and its options, in declaration order), for results files and reports:
// "pxflow --disable-isa avx512bw bench --backends cpu --batch 1,16 --json b.json".
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "backend.hpp"
#include "guarded_child.hpp"
#include "option_spec.hpp"
#include "shell_word.hpp"

namespace pxflow::cli {

using pxflow::shell_word;

// The options given to `app`, each with its value (none for a flag), an option given several
// times once per value.
inline std::vector<std::pair<std::string, std::optional<std::string>>> given_option_list(
    const CommandSpec& app) {
  std::vector<std::pair<std::string, std::optional<std::string>>> given;
  for (const OptionSpec& opt : app.options) {
    if (opt.count() == 0) continue;
    if (opt.is_flag())
      given.push_back({opt.name(), std::nullopt});
    else
      for (const std::string& value : opt.results) given.push_back({opt.name(), value});
  }
  return given;
}

inline std::string given_options(const CommandSpec& app) {
  std::string line;
  for (const auto& [name, value] : given_option_list(app)) {
    line.append(" ").append(name);
    if (value) line.append(" ").append(shell_word(*value));
  }
  return line;
}

// The global options given with the subcommand (--device-timeout, the families' --disable-isa,
// --dut ...): " --device-timeout 2 --dut 'py=exec:python3 dev.py'", or "". An option with an alias
// is recorded under its first name (--dut-timeout as --device-timeout). Every command
// another one runs in-process needs them to be rerun as it ran.
inline std::string global_options(const CommandSpec& sub) {
  const CommandSpec* parent = sub.parent;
  return parent ? given_options(*parent) : std::string();
}

inline std::string given_command_line(const CommandSpec& sub) {
  return "pxflow" + global_options(sub) + " " + sub.name + given_options(sub);
}

// The command line of `pxflow check`'s workers (isolated_row.hpp): this binary, the global
// options given with `sub` (they shape the rows: --dut, --disable-isa, --device-timeout), then
// `check` with the backends' options; the worker adds --check-worker ROW.
inline std::vector<std::string> check_worker_command(const CommandSpec& sub,
                                                     const BackendOptions& options) {
  std::vector<std::string> argv = {own_executable()};
  if (const CommandSpec* parent = sub.parent)
    for (const auto& [name, value] : given_option_list(*parent)) {
      argv.push_back(name);
      if (value) argv.push_back(*value);
    }
  argv.push_back("check");
  if (options.threads != 0) argv.insert(argv.end(), {"--threads", std::to_string(options.threads)});
  if (!options.device.empty()) argv.insert(argv.end(), {"--device", options.device});
  return argv;
}

}  // namespace pxflow::cli
