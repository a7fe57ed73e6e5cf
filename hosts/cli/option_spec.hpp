// How a command declares its options: a list of OptionSpec in a CommandSpec, owned by pxflow.
// Only cli11_binding.cpp knows the parser (CLI11): it turns the declarations into the parser's
// options, and after a parse fills each OptionSpec's `results` and each CommandSpec's `parsed`.
// The same declarations give `pxflow --list-options` (options_listing.cpp), from which the
// generated tests take every option (tests/cli), so a new option is tested without a new test.
#pragma once
#include <cstdint>
#include <deque>
#include <functional>
#include <list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "path_options.hpp"

namespace pxflow::cli {

// A check of a value's text: "" when it is good, else what is wrong with it. `name` is what the
// value is, in --help ("LIST", "SEED").
struct ValueCheck {
  std::function<std::string(const std::string&)> problem;
  std::string name;
};

// Where a value goes. A flag's target is a bool (or none: on_flag); a list takes every value.
using OptionTarget = std::variant<std::monostate, bool*, std::string*, int*, long*, std::uint64_t*,
                                  double*, std::vector<std::string>*>;

struct OptionSpec {
  std::string names;  // "--threads"; "--a,--b" (aliases); a positional's "PREV"
  std::string help;
  OptionTarget target;
  std::function<void()> on_flag;  // a flag without a target: called when given
  std::string renamed_to;         // an old spelling, refused with one line naming the new one
  std::string value_name;         // in --help: "N", "FILE"; empty: the target type's
  std::optional<std::pair<long, long>> range;     // an integer's bounds
  std::optional<std::pair<double, double>> real;  // a real's bounds (real_options.hpp)
  std::optional<ValueCheck> check;
  std::vector<std::string> one_of;            // the values allowed, when they are few
  std::optional<DeclaredPath> path;           // what pxflow does with a path (path_options.hpp)
  std::optional<std::pair<int, int>> values;  // values per use, min and max (default: the type's)
  bool show_default = false;                  // --help shows the target's value before the parse
  bool required = false;
  bool one_word = false;  // a list option takes one value per use (`--set K=V file` keeps file)
  bool hidden = false;    // not in --help (old spellings, the worker mode)
  enum class Repeat { Type, Each, Once } repeat = Repeat::Type;  // given again: kept, or refused

  std::vector<std::string> results;  // after a parse: the values given, one a use for a flag

  OptionSpec& type(std::string name) { return value_name = std::move(name), *this; }
  OptionSpec& in_range(long lo, long hi) { return range = {{lo, hi}}, *this; }
  OptionSpec& real_in(double lo, double hi) { return real = {{lo, hi}}, *this; }
  OptionSpec& checked(ValueCheck c) { return check = std::move(c), *this; }
  OptionSpec& choices(std::vector<std::string> allowed) {
    return one_of = std::move(allowed), *this;
  }
  OptionSpec& path_kind(PathKind kind, std::string suffix = "") {
    return path = DeclaredPath{kind, std::move(suffix)}, *this;
  }
  OptionSpec& value_count(int min, int max) { return values = {{min, max}}, *this; }
  OptionSpec& with_default() { return show_default = true, *this; }
  OptionSpec& needed() { return required = true, *this; }
  OptionSpec& one_word_each() { return one_word = true, *this; }
  OptionSpec& unlisted() { return hidden = true, *this; }
  OptionSpec& repeats(Repeat r) { return repeat = r, *this; }

  std::string name() const;  // the first of `names`
  bool is_flag() const;      // takes no value
  bool is_positional() const { return !names.empty() && names[0] != '-'; }
  bool named(std::string_view name) const;  // one of `names`
  std::size_t count() const { return results.size(); }
};

// A command, or a command's own subcommand (vectors verify), or the top level (its options are
// the global ones). References returned by add() stay valid as more are added.
struct CommandSpec {
  std::string name, description, footer;
  std::deque<OptionSpec> options;
  std::list<CommandSpec> subcommands;
  const CommandSpec* parent = nullptr;
  bool parsed = false;  // after a parse: this command was given

  CommandSpec(std::string n = "", std::string d = "")
      : name(std::move(n)), description(std::move(d)) {}
  CommandSpec& add_subcommand(std::string n, std::string d);

  OptionSpec& add(std::string names, OptionTarget target, std::string help = "");
  OptionSpec& flag(std::string names, bool& target, std::string help);
  OptionSpec& flag_callback(std::string names, std::function<void()> call, std::string help);
  OptionSpec& renamed(std::string old_name, std::string new_name);

  const OptionSpec* find(std::string_view name) const;  // by any of its names, hidden too
  std::size_t count(std::string_view name) const;       // uses of the option given
};

}  // namespace pxflow::cli
