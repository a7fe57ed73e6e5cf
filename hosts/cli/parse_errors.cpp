#include "parse_errors.hpp"

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

std::string reword(const CLI::ParseError& e) {
  const std::string what = e.what();
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

}  // namespace

std::string describe_parse_error(const CLI::ParseError& e, const std::string& command) {
  return reword(e) + " (see pxflow " + (command.empty() ? "" : command + " ") + "--help)";
}

}  // namespace pxflow::cli
