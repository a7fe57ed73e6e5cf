#include <string_view>

#include "commands.hpp"
#include "errors.hpp"

namespace pxflow::cli {

void ProblemOptions::add_to(CommandSpec& app) {
  std::string profiles;
  for (const auto& n : profile_names()) profiles += (profiles.empty() ? "" : ", ") + n;
  std::string keys;
  // gyro_comp is a key of the spec's parameters, but pxflow takes no gyro rates (resolve()).
  for (const auto& k : param_keys())
    keys += (keys.empty() ? "" : ", ") + k + (k == "gyro_comp" ? " (0 only)" : "");
  app.add("--profile", &profile, "Parameter profile: " + profiles).with_default().type("NAME");
  app.add("--set", &sets, "Override one parameter, KEY=VALUE (repeatable). Keys: " + keys)
      .type("KEY=VALUE")
      .one_word_each();  // one KEY=VALUE each: `--set S=7 video.avi` keeps the file
}

Params ProblemOptions::resolve(std::optional<std::pair<int, int>> frame) const {
  Params p = pxflow::profile(profile);
  bool width_set = false, height_set = false;
  for (const auto& kv : sets) {
    const std::string_view key = set_param_assignment(p, kv);
    width_set |= key == "width";
    height_set |= key == "height";
  }
  if (frame) {
    const auto [w, h] = *frame;
    if ((width_set && p.width != w) || (height_set && p.height != h))
      throw InputError("frames are " + std::to_string(w) + "x" + std::to_string(h) +
                       " but --set asks for " + std::to_string(p.width) + "x" +
                       std::to_string(p.height));
    p.width = w;
    p.height = h;
  }
  require_no_gyro_comp(p);
  validate(p);
  return p;
}

bool ProblemOptions::sets_key(std::string_view key) const {
  for (const auto& kv : sets)
    if (kv.size() > key.size() && kv.compare(0, key.size(), key) == 0 && kv[key.size()] == '=')
      return true;
  return false;
}

}  // namespace pxflow::cli
