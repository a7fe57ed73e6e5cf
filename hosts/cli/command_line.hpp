// The command line a subcommand actually ran, rebuilt from what CLI11 parsed (global options,
// then the subcommand and its options, in declaration order), for results files and reports:
// "pxflow --disable-isa avx512bw bench --backends cpu --batch 1,16 --json b.json".
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "shell_word.hpp"

namespace pxflow::cli {

using pxflow::shell_word;

inline std::string given_options(const CLI::App& app) {
  std::string line;
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->count() == 0 || opt->get_name() == "--help" || opt->get_name() == "--version")
      continue;
    const std::string name = opt->get_name();
    if (opt->get_items_expected_min() == 0) {  // a flag
      line.append(" ").append(name);
      continue;
    }
    for (const std::string& value : opt->results())
      line.append(" ").append(name).append(" ").append(shell_word(value));
  }
  return line;
}

// The global options given with the subcommand (--device-timeout, the families' --disable-isa,
// --dut ...): " --device-timeout 2 --dut 'py=exec:python3 dev.py'", or "". An option with an alias
// is recorded under its first name (--dut-timeout as --device-timeout). Every command
// another one runs in-process needs them to be rerun as it ran.
inline std::string global_options(const CLI::App& sub) {
  const CLI::App* parent = sub.get_parent();
  return parent ? given_options(*parent) : std::string();
}

inline std::string given_command_line(const CLI::App& sub) {
  return "pxflow" + global_options(sub) + " " + sub.get_name() + given_options(sub);
}

}  // namespace pxflow::cli
