#include "options_listing.hpp"

#include "json_document.hpp"
#include "path_options.hpp"
#include "real_options.hpp"
#include "sample_data.hpp"

namespace pxflow::cli {
namespace {

Json option_json(const CLI::Option* o) {
  Json j{{"name", o->get_name()},
         {"positional", o->get_lnames().empty() && o->get_snames().empty()},
         {"takes_value", o->get_items_expected_max() > 0},
         {"type_name", o->get_type_name()},
         {"required", o->get_required()},
         {"hidden", o->get_group().empty()},
         {"repeatable", o->get_items_expected_max() > 1 ||
                            o->get_multi_option_policy() == CLI::MultiOptionPolicy::TakeAll}};
  if (const auto r = declared_real(o)) j["real"] = {r->first, r->second};
  if (const auto d = declared_path(o)) {
    j["path"] = path_kind_name(d->kind);
    if (!d->suffix.empty()) j["suffix"] = d->suffix;
  }
  return j;
}

Json options_json(const CLI::App& app) {
  Json list = Json::array();
  for (const CLI::Option* o : app.get_options())
    if (o->get_name() != "--help" && o->get_name() != "--version") list.push_back(option_json(o));
  return list;
}

}  // namespace

std::string list_options_json(const CLI::App& app, const std::vector<Command>& commands) {
  Json j{{"sample_data", kSampleDataDir},  // --data's default, read only by the tests too
         {"global", options_json(app)},
         {"commands", Json::array()}};
  for (const Command& c : commands) {
    Json subcommands = Json::array();
    for (const CLI::App* sub : c.app->get_subcommands([](const CLI::App*) { return true; }))
      subcommands.push_back({{"name", sub->get_name()}, {"options", options_json(*sub)}});
    j["commands"].push_back({{"name", c.app->get_name()},
                             {"options", options_json(*c.app)},
                             {"subcommands", subcommands},
                             {"matrix_runs", c.matrix_runs},
                             {"long_runs", c.long_runs}});
  }
  return json_document(j);
}

}  // namespace pxflow::cli
