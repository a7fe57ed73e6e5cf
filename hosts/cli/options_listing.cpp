#include "options_listing.hpp"

#include <nlohmann/json.hpp>

#include "json_document.hpp"
#include "real_options.hpp"
#include "sample_data.hpp"

namespace pxflow::cli {
namespace {

// What --help calls the value: the declared name, else the target type's, then what each check
// allows, as CLI11 writes it ("N:INT in [0 - 1024]", "bin|c:{bin,c}").
std::string shown_type(const OptionSpec& o) {
  if (o.is_flag()) return "";
  std::string name = o.value_name;
  if (name.empty())
    name = std::holds_alternative<int*>(o.target) || std::holds_alternative<long*>(o.target) ? "INT"
           : std::holds_alternative<std::uint64_t*>(o.target) ? "UINT"
           : std::holds_alternative<double*>(o.target)        ? "FLOAT"
                                                              : "TEXT";
  if (o.range)
    name += ":INT in [" + std::to_string(o.range->first) + " - " + std::to_string(o.range->second) +
            "]";
  if (o.check) name += ":" + o.check->name;
  if (o.real) name += ":" + real_value_name(o.real->first, o.real->second);
  if (!o.one_of.empty()) {
    std::string set;
    for (const std::string& v : o.one_of) set += (set.empty() ? "" : ",") + v;
    name += ":{" + set + "}";
  }
  return name;
}

// Values per use at most: a list takes any number unless declared.
int most_values(const OptionSpec& o) {
  if (o.values) return o.values->second;
  if (o.is_flag()) return 0;
  return std::holds_alternative<std::vector<std::string>*>(o.target) ? 2 : 1;
}

Json option_json(const OptionSpec& o) {
  Json j{{"name", o.name()},
         {"positional", o.is_positional()},
         {"takes_value", most_values(o) > 0},
         {"type_name", shown_type(o)},
         {"required", o.required},
         {"hidden", o.hidden},
         {"repeatable", most_values(o) > 1 || o.repeat == OptionSpec::Repeat::Each}};
  if (o.real) j["real"] = {o.real->first, o.real->second};
  if (o.path) {
    j["path"] = path_kind_name(o.path->kind);
    if (!o.path->suffix.empty()) j["suffix"] = o.path->suffix;
  }
  return j;
}

Json options_json(const CommandSpec& spec) {
  Json list = Json::array();
  for (const OptionSpec& o : spec.options) list.push_back(option_json(o));
  return list;
}

}  // namespace

std::string list_options_json(const CommandSpec& app, const std::vector<Command>& commands) {
  Json j{{"sample_data", kSampleDataDir},  // --data's default, read only by the tests too
         {"global", options_json(app)},
         {"commands", Json::array()}};
  for (const Command& c : commands) {
    Json subcommands = Json::array();
    for (const CommandSpec& sub : c.spec->subcommands)
      subcommands.push_back({{"name", sub.name}, {"options", options_json(sub)}});
    j["commands"].push_back({{"name", c.spec->name},
                             {"options", options_json(*c.spec)},
                             {"subcommands", subcommands},
                             {"matrix_runs", c.matrix_runs},
                             {"long_runs", c.long_runs}});
  }
  return json_document(j);
}

}  // namespace pxflow::cli
