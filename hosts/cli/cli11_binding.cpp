// pxflow's option declarations translated to CLI11: the only file that includes it.
#include "cli11_binding.hpp"

#include <CLI/CLI.hpp>
#include <map>
#include <stdexcept>
#include <type_traits>

#include "real_options.hpp"

namespace pxflow::cli {
namespace {

using Bound = std::map<OptionSpec*, CLI::Option*>;

// The option with its target: a flag for a bool, CLI11's own conversion for every other type.
CLI::Option* add_target(CLI::App& app, const OptionSpec& o) {
  if (!o.renamed_to.empty()) {
    const std::string old_name = o.name(), new_name = o.renamed_to;
    // Thrown from the callback with its own name: CLI11 names a hidden option's errors "".
    return app
        .add_option_function<std::string>(o.names,
                                          [old_name, new_name](const std::string&) {
                                            throw CLI::ValidationError(old_name,
                                                                       "renamed: give " + new_name);
                                          })
        ->expected(0, 1);  // alone too: CLI11's "needs a value" would name it ""
  }
  if (o.on_flag) return app.add_flag_callback(o.names, o.on_flag, o.help);
  return std::visit(
      [&](auto target) -> CLI::Option* {
        if constexpr (std::is_same_v<decltype(target), std::monostate>) {
          throw std::logic_error("option " + o.names + " declares no target");
        } else {
          using T = std::remove_pointer_t<decltype(target)>;
          if constexpr (std::is_same_v<T, bool>) {
            return app.add_flag(o.names, *target, o.help);
          } else {
            CLI::Option* opt = app.add_option(o.names, *target, o.help);
            // An integer's bounds in the target's own type: a value beyond that type is refused
            // as out of range, as CLI11's Range of it does.
            if constexpr (std::is_same_v<T, int> || std::is_same_v<T, long>) {
              if (o.range) opt->check(CLI::Range(T(o.range->first), T(o.range->second)));
            } else if (o.range) {  // a real's range is real_in(): nan and inf refused too
              throw std::logic_error("option " + o.names + ": in_range() on a non-integer");
            }
            return opt;
          }
        }
      },
      o.target);
}

CLI::Validator value_check(const ValueCheck& c) {
  return CLI::Validator([problem = c.problem](std::string& s) { return problem(s); }, c.name);
}

CLI::Validator real_check(double lo, double hi) {
  return CLI::Validator([lo, hi](std::string& text) { return real_value_problem(text, lo, hi); },
                        real_value_name(lo, hi));
}

CLI::Option* add(CLI::App& app, const OptionSpec& o) {
  CLI::Option* opt = add_target(app, o);
  if (!o.value_name.empty()) opt->type_name(o.value_name);
  if (o.values)
    o.values->first == o.values->second ? opt->expected(o.values->first)
                                        : opt->expected(o.values->first, o.values->second);
  if (o.check) opt->check(value_check(*o.check));
  if (o.real) opt->check(real_check(o.real->first, o.real->second));
  if (!o.one_of.empty()) opt->check(CLI::IsMember(o.one_of));
  if (o.show_default) opt->capture_default_str();
  if (o.required) opt->required();
  if (o.one_word) opt->allow_extra_args(false);
  if (o.repeat != OptionSpec::Repeat::Type)
    opt->multi_option_policy(o.repeat == OptionSpec::Repeat::Each ? CLI::MultiOptionPolicy::TakeAll
                                                                  : CLI::MultiOptionPolicy::Throw);
  if (o.hidden) opt->group("");
  return opt;
}

void bind(CLI::App& app, CommandSpec& spec, Bound& bound, std::map<CommandSpec*, CLI::App*>& apps) {
  apps[&spec] = &app;
  for (OptionSpec& o : spec.options) bound[&o] = add(app, o);
  for (CommandSpec& sub : spec.subcommands) {
    sub.parent = &spec;
    bind(*app.add_subcommand(sub.name, sub.description), sub, bound, apps);
  }
  // After the subcommands: CLI11 gives a new subcommand its parent's footer.
  if (!spec.footer.empty()) app.footer(spec.footer);
}

}  // namespace

ParseOutcome parse_command_line(CommandSpec& top, const std::function<std::string()>& version,
                                int argc, char** argv) {
  CLI::App app{top.description};
  app.set_version_flag("--version", version);
  app.require_subcommand(1);
  app.fallthrough();  // global options may follow the subcommand
  Bound bound;
  std::map<CommandSpec*, CLI::App*> apps;
  bind(app, top, bound, apps);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return {app.exit(e), ""};
  } catch (const CLI::CallForAllHelp& e) {
    return {app.exit(e), ""};
  } catch (const CLI::CallForVersion& e) {
    return {app.exit(e), ""};
  } catch (const CLI::ParseError& e) {
    return {std::nullopt, e.what()};
  }
  for (auto& [spec, option] : bound) spec->results = option->results();
  for (auto& [spec, sub] : apps) spec->parsed = sub->parsed();
  return {};
}

}  // namespace pxflow::cli
