#include <string_view>

#include "commands.hpp"
#include "errors.hpp"

namespace pxflow::cli {

void ProblemOptions::add_to(CLI::App& app) {
  std::string profiles;
  for (const auto& n : profile_names()) profiles += (profiles.empty() ? "" : ", ") + n;
  std::string keys;
  // gyro_comp is a key of the spec's parameters, but pxflow takes no gyro rates (resolve()).
  for (const auto& k : param_keys())
    keys += (keys.empty() ? "" : ", ") + k + (k == "gyro_comp" ? " (0 only)" : "");
  app.add_option("--profile", profile, "Parameter profile: " + profiles)
      ->capture_default_str()
      ->type_name("NAME");
  app.add_option("--set", sets, "Override one parameter, KEY=VALUE (repeatable). Keys: " + keys)
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);  // one KEY=VALUE each: `--set S=7 video.avi` keeps the file
}

Params ProblemOptions::resolve(std::optional<std::pair<int, int>> frame) const {
  Params p = pxflow::profile(profile);
  bool width_set = false, height_set = false;
  for (const auto& kv : sets) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--set '" + kv + "': expected KEY=VALUE, e.g. --set search_radius=8");
    const std::string_view key(kv.data(), eq);
    set_param(p, key, std::string_view(kv).substr(eq + 1));
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
  if (p.gyro_comp)
    throw InputError(
        "--set gyro_comp=1: pxflow takes no gyro rates, so the compensation would "
        "have nothing to add; leave gyro_comp at 0");
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
