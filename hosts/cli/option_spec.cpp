#include "option_spec.hpp"

namespace pxflow::cli {

std::string OptionSpec::name() const { return names.substr(0, names.find(',')); }

bool OptionSpec::is_flag() const {
  return std::holds_alternative<bool*>(target) || static_cast<bool>(on_flag);
}

bool OptionSpec::named(std::string_view wanted) const {
  std::string_view rest = names;
  while (!rest.empty()) {
    const std::size_t comma = rest.find(',');
    if (rest.substr(0, comma) == wanted) return true;
    rest = comma == std::string_view::npos ? "" : rest.substr(comma + 1);
  }
  return false;
}

CommandSpec& CommandSpec::add_subcommand(std::string n, std::string d) {
  CommandSpec& sub = subcommands.emplace_back(std::move(n), std::move(d));
  sub.parent = this;
  return sub;
}

OptionSpec& CommandSpec::add(std::string n, OptionTarget target, std::string help) {
  OptionSpec& o = options.emplace_back();
  o.names = std::move(n), o.target = target, o.help = std::move(help);
  return o;
}

OptionSpec& CommandSpec::flag(std::string n, bool& target, std::string help) {
  return add(std::move(n), &target, std::move(help));
}

OptionSpec& CommandSpec::flag_callback(std::string n, std::function<void()> call,
                                       std::string help) {
  OptionSpec& o = add(std::move(n), std::monostate{}, std::move(help));
  o.on_flag = std::move(call);
  return o;
}

OptionSpec& CommandSpec::renamed(std::string old_name, std::string new_name) {
  OptionSpec& o = add(std::move(old_name), std::monostate{});
  o.renamed_to = std::move(new_name);
  o.hidden = true;
  return o;
}

const OptionSpec* CommandSpec::find(std::string_view wanted) const {
  for (const OptionSpec& o : options)
    if (o.named(wanted)) return &o;
  return nullptr;
}

std::size_t CommandSpec::count(std::string_view wanted) const {
  const OptionSpec* o = find(wanted);
  return o ? o->count() : 0;
}

}  // namespace pxflow::cli
