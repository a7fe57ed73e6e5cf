// pxflow's command line: parses the subcommand, runs it, and turns every error into one line on
// stderr: exit 2 for bad input, 1 for a failure while running, 128 + N after a stop signal N
// (129 SIGHUP, 130 SIGINT, 141 SIGPIPE or EPIPE on standard output, 143 SIGTERM; the signal
// policy is core/interrupt.hpp's).
#include <cstdio>
#include <new>

#include "cli11_binding.hpp"
#include "cli_extension.hpp"
#include "commands.hpp"
#include "device_wait.hpp"
#include "errors.hpp"
#include "frame_io.hpp"
#include "help_sections.hpp"
#include "interrupt.hpp"
#include "options_listing.hpp"
#include "output_plan.hpp"
#include "parse_errors.hpp"
#include "pxflow_app.hpp"
#include "pxflow_version.h"
#include "registry.hpp"

namespace pxflow {

namespace {

// "pxflow 0.1 (commit ..., GCC 12.2.0; families: reference, cpu, ...)"
std::string version_text() {
  std::string families;
  for (const BackendFamily& f : backend_families())
    families += (families.empty() ? "" : ", ") + f.name;
  return std::string("pxflow ") + PXFLOW_VERSION + " (commit " + PXFLOW_COMMIT + ", " +
         PXFLOW_COMPILER + "; backend families: " + families + ")";
}

// The families' global options (e.g. the cpu family's --disable-isa), each with the values given
// for it, applied before the command runs.
using FamilyOptionValues = std::vector<std::pair<const FamilyOption*, std::vector<std::string>>>;

// Declares the families' global options on the top level, --device-timeout first: shared by every
// family that waits on a device, declared once here. The parser writes each option's values into
// the returned list's elements, so it is moved, never copied or grown, after this.
FamilyOptionValues declare_family_options(cli::CommandSpec& app) {
  static const FamilyOption device_timeout = device_timeout_option();
  FamilyOptionValues family_options = {{&device_timeout, {}}};
  for (const BackendFamily& f : backend_families())
    for (const FamilyOption& opt : f.options) family_options.push_back({&opt, {}});
  for (auto& [opt, values] : family_options) {
    // One value per occurrence; only a repeatable option may occur more than once.
    cli::OptionSpec& flag =
        app.add(opt->flag, &values, opt->help).value_count(1, 1).type(opt->value_name);
    if (opt->reads_file) flag.path_kind(cli::PathKind::InputFile);
    flag.repeats(opt->repeatable ? cli::OptionSpec::Repeat::Each : cli::OptionSpec::Repeat::Once);
  }
  return family_options;
}

// pxflow's own commands, then the families' (their CLI extensions).
std::vector<cli::Command> declare_commands(cli::CommandSpec& app) {
  std::vector<cli::Command> commands = {
      cli::add_flow_command(app),   cli::add_check_command(app),    cli::add_bench_command(app),
      cli::add_report_command(app), cli::add_accuracy_command(app), cli::add_backends_command(app),
      cli::add_merge_command(app),  cli::add_compare_command(app)};
  for (const cli::CliExtension& e : cli::registered_cli_extensions())
    if (e.add_command) commands.push_back(e.add_command(app));
  return commands;
}

// Every command's --help (and so its man page) ends with its own footer, the global options,
// the exit status, the environment and its examples; pxflow --help with the last three.
void end_help_texts(cli::CommandSpec& app, const std::vector<cli::Command>& commands,
                    const FamilyOptionValues& family_options) {
  std::string globals = "Global options (before or after the command; see pxflow --help):";
  for (const auto& [opt, values] : family_options) globals += "\n  " + opt->flag + "  " + opt->help;
  for (const auto& c : commands) {
    const std::string own = c.spec->footer;
    c.spec->footer =
        (own.empty() ? "" : own + "\n\n") + globals + "\n\n" + cli::help_sections(c.examples);
  }
  app.footer = cli::help_sections(cli::first_examples(commands));
}

// Whether argv[1] is a command or a top-level option; if not, says so on stderr. `command` is
// the command named, or empty.
bool first_argument_known(const cli::CommandSpec& app, const std::vector<cli::Command>& commands,
                          int argc, char** argv, std::string& command) {
  if (argc > 1 && argv[1][0] != '-') {
    for (const auto& c : commands)
      if (c.spec->name == argv[1]) command = argv[1];
    if (command.empty()) {
      std::fprintf(stderr, "pxflow: error: unknown command '%s' (see pxflow --help)\n", argv[1]);
      return false;
    }
  } else if (argc > 1) {
    // An option before any command must be one of the top level's (CLI11 would report a missing
    // command instead of the unknown option).
    const std::string arg = argv[1];
    const std::string name = arg.substr(0, arg.find('='));
    if (!cli::declares_global(app, name)) {
      std::fprintf(stderr, "pxflow: error: unknown option %s%s (see pxflow --help)\n", name.c_str(),
                   cli::nearest_option(name, app).c_str());
      return false;
    }
  }
  return true;
}

// The parser's error as one line on stderr: a misspelt option is named, whatever the parser made
// of it and of its value.
void print_parse_error(const std::string& error, const cli::CommandSpec& app,
                       const std::vector<cli::Command>& commands, const std::string& command,
                       int argc, char** argv) {
  const cli::CommandSpec* sub = nullptr;
  for (const auto& c : commands)
    if (c.spec->name == command) sub = c.spec;
  const std::string unknown =
      cli::unknown_option(std::vector<std::string>(argv + 1, argv + argc), app, sub);
  if (!unknown.empty()) {
    std::fprintf(stderr, "pxflow: error: %s (see pxflow %s--help)\n", unknown.c_str(),
                 command.empty() ? "" : (command + " ").c_str());
    return;
  }
  std::fprintf(stderr, "pxflow: error: %s\n", cli::describe_parse_error(error, command).c_str());
}

// Applies the families' options and runs the parsed command. Returns its exit status.
int run_parsed_command(const cli::CommandSpec& app, const std::vector<cli::Command>& commands,
                       const FamilyOptionValues& family_options) {
  for (const BackendFamily& f : backend_families())
    if (f.check_environment) f.check_environment();
  for (const auto& [opt, values] : family_options)
    for (const std::string& value : values) opt->apply(value);
  for (const auto& c : commands)
    if (c.spec->parsed) {
      cli::note_given_inputs(app);  // before any plan: its outputs are checked against them
      cli::note_given_inputs(*c.spec);
      for (const cli::CommandSpec& sub : c.spec->subcommands)
        if (sub.parsed) cli::note_given_inputs(sub);
      const int code = c.run();
      check_stdout();  // output that was lost is a failure, never a silent exit 0
      return code;
    }
  return 2;
}

// run_parsed_command, every error it throws turned into one line on stderr and its exit status.
int run_reporting_errors(const cli::CommandSpec& app, const std::vector<cli::Command>& commands,
                         const FamilyOptionValues& family_options) {
  try {
    return run_parsed_command(app, commands, family_options);
  } catch (const InputError& e) {
    std::fprintf(stderr, "pxflow: error: %s\n", e.what());
    return 2;
  } catch (const Interrupted& e) {
    std::fflush(stdout);  // what was printed goes out first, never cut by this line on a terminal
    std::fprintf(stderr, "pxflow: interrupted: %s%s\n", e.what(),
                 files_changed() == 0 ? "; no output file was changed" : "");
    return 128 + e.signal;
  } catch (const OutputError& e) {
    std::fprintf(stderr, "pxflow: error: %s\n", e.what());
    return 1;
  } catch (const BackendError& e) {
    std::fprintf(stderr, "pxflow: backend failed: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "pxflow: error: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pxflow: internal error: %s\n", e.what());
    return 1;
  }
}

}  // namespace

int run_pxflow(int argc, char** argv) {
  install_interrupt_handlers();
  cli::CommandSpec app{
      "", "pxflow: the PX4FLOW optical-flow kernel, cross-checked bit for bit across backends"};
  FamilyOptionValues family_options = declare_family_options(app);
  const std::vector<cli::Command> commands = declare_commands(app);
  end_help_texts(app, commands, family_options);
  // For the generated tests (path_options.hpp): every option, its kind, every command's runs.
  if (argc == 2 && std::string(argv[1]) == "--list-options") {
    std::fputs(cli::list_options_json(app, commands).c_str(), stdout);
    return 0;
  }
  std::string command;  // the subcommand being parsed, for "see pxflow CMD --help"
  if (!first_argument_known(app, commands, argc, argv, command)) return 2;
  if (const cli::ParseOutcome parse = cli::parse_command_line(app, version_text, argc, argv);
      parse.exit_code) {
    return *parse.exit_code;
  } else if (!parse.error.empty()) {
    print_parse_error(parse.error, app, commands, command, argc, argv);
    return 2;
  }
  return run_reporting_errors(app, commands, family_options);
}

}  // namespace pxflow
