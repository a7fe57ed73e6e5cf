#include "parse_errors.hpp"

#include <algorithm>
#include <regex>

namespace pxflow::cli {
namespace {

// "600.000000" -> "600", "0.250000" -> "0.25": CLI::Range prints its bounds with std::to_string.
std::string trim_number(std::string n) {
  if (n.find('.') == std::string::npos) return n;
  while (n.back() == '0') n.pop_back();
  if (n.back() == '.') n.pop_back();
  return n;
}

std::string reword(const std::string& what) {
  std::smatch m;
  // CLI::Range: "--cases: Value 1e3 not in range 1 to 100000000"
  static const std::regex range(R"(^(\S+): Value (.*) not in range (\S+) to (\S+)$)");
  if (std::regex_match(what, m, range))
    return m[1].str() + ": '" + m[2].str() + "': must be a number from " + trim_number(m[3]) +
           " to " + trim_number(m[4]);
  // Given twice: "--seed: At Most 1 required but received 2"
  static const std::regex at_most(R"(^(\S+): At Most (\d+) required but received (\d+)$)");
  if (std::regex_match(what, m, at_most))
    return m[1].str() + ": given " + m[3].str() + " times: give it " +
           (m[2] == "1" ? std::string("once") : "at most " + m[2].str() + " times");
  // No value: "--backend: 1 required TEXT missing"
  static const std::regex missing_value(R"(^(\S+): \d+ required \S+ missing$)");
  if (std::regex_match(what, m, missing_value)) return m[1].str() + ": needs a value";
  // A required option or argument: "--out is required", "NEXT is required"
  static const std::regex required(R"(^(\S+) is required$)");
  if (std::regex_match(what, m, required)) return m[1].str() + ": missing: it is required";
  if (what == "A subcommand is required")
    return "no command given: the commands are listed by pxflow --help";
  // Extras: "The following argument(s) was/were not expected: -V c"
  static const std::regex extras(R"(^The following arguments? (?:was|were) not expected: (.*)$)");
  if (std::regex_match(what, m, extras)) {
    const std::string first = m[1].str().substr(0, m[1].str().find(' '));
    return first.size() > 1 && first[0] == '-' ? "unknown option " + first
                                               : "unexpected argument '" + first + "'";
  }
  // A validator's own text after "NAME: " (pxflow's validators already say what is allowed).
  return what;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// Whether `command` or one of its own subcommands (vectors verify) declares `name`.
bool declares(const CommandSpec& command, const std::string& name) {
  if (command.find(name) != nullptr || name == "--help") return true;
  for (const CommandSpec& sub : command.subcommands)
    if (sub.find(name) != nullptr) return true;
  return false;
}

// The long names --help lists, in its order: --help, the top level's --version, the options.
std::vector<std::string> listed_names(const CommandSpec& app) {
  std::vector<std::string> names = {"--help"};
  if (app.parent == nullptr) names.push_back("--version");
  for (const OptionSpec& opt : app.options) {
    if (opt.hidden) continue;  // old spellings, the worker mode
    for (std::size_t start = 0; start < opt.names.size();) {
      const std::size_t end = std::min(opt.names.find(',', start), opt.names.size());
      const std::string name = opt.names.substr(start, end - start);
      if (name.compare(0, 2, "--") == 0) names.push_back(name);
      start = end + 1;
    }
  }
  return names;
}

}  // namespace

bool declares_global(const CommandSpec& app, const std::string& name) {
  return app.find(name) != nullptr || name == "-h" || name == "--help" || name == "--version";
}

std::string nearest_option(const std::string& name, const CommandSpec& app) {
  std::string best;
  std::size_t best_distance = 3;  // within two edits: a slip, not another option
  for (const std::string& long_name : listed_names(app)) {
    const std::size_t d = edit_distance(name, long_name);
    if (d < best_distance) best_distance = d, best = long_name;
  }
  return best.empty() ? "" : " (did you mean " + best + "?)";
}

std::string unknown_option(const std::vector<std::string>& args, const CommandSpec& app,
                           const CommandSpec* command) {
  for (const std::string& arg : args) {
    if (arg == "--") break;  // what follows are arguments
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) continue;
    const std::string name = arg.substr(0, arg.find('='));
    if ((command && declares(*command, name)) || declares_global(app, name)) continue;
    return "unknown option " + name + nearest_option(name, command ? *command : app);
  }
  return "";
}

std::string describe_parse_error(const std::string& what, const std::string& command) {
  return reword(what) + " (see pxflow " + (command.empty() ? "" : command + " ") + "--help)";
}

}  // namespace pxflow::cli
