#include "params.hpp"

#include <charconv>

#include "errors.hpp"
#include "param_fields.hpp"

namespace pxflow {
namespace {

struct NamedProfile {
  const char* name;
  Params params;
};

// SPEC §1. px4flow-64 is the ISCAS 2022 configuration; px4flow-head is today's firmware.
const std::vector<NamedProfile>& profiles() {
  static const std::vector<NamedProfile> table = {
      {kDefaultProfile.data(), Params{}},
      {"px4flow-head",
       [] {
         Params p;
         p.search_radius = 8;
         p.blocks = 5;
         p.hist_filter = false;
         return p;
       }()},
  };
  return table;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

const std::vector<std::string>& profile_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto& p : profiles()) v.push_back(p.name);
    return v;
  }();
  return names;
}

Params profile(std::string_view name) {
  for (const auto& p : profiles())
    if (name == p.name) return p.params;
  throw InputError("unknown profile '" + std::string(name) +
                   "' (known: " + joined(profile_names()) + ")");
}

std::span<const ParamField> param_fields() {
  static constexpr ParamField kFields[] = {
      {"width", &Params::width, nullptr},
      {"height", &Params::height, nullptr},
      {"search_radius", &Params::search_radius, nullptr},
      {"tile", &Params::tile, nullptr},
      {"blocks", &Params::blocks, nullptr},
      {"feature_threshold", &Params::feature_threshold, nullptr},
      {"sad_threshold", &Params::sad_threshold, nullptr},
      {"hist_filter", nullptr, &Params::hist_filter},
      {"min_count", &Params::min_count, nullptr},
      {"gyro_comp", nullptr, &Params::gyro_comp},
  };
  return kFields;
}

const std::vector<std::string>& param_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> v;
    for (const ParamField& f : param_fields()) v.push_back(f.key);
    return v;
  }();
  return keys;
}

int parse_int(std::string_view text, std::string_view what, std::int64_t lo, std::int64_t hi) {
  std::int64_t v = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end)
    throw InputError(std::string(what) + ": '" + std::string(text) + "' is not an integer");
  if (v < lo || v > hi)
    throw InputError(std::string(what) + ": " + std::to_string(v) + " is outside " +
                     std::to_string(lo) + ".." + std::to_string(hi));
  return static_cast<int>(v);
}

void set_param(Params& p, std::string_view key, std::string_view value) {
  const std::string what = "--set " + std::string(key);
  // Parse with a wide range here; validate() owns the real limits so that profile values and
  // overrides are checked by the same code.
  for (const ParamField& f : param_fields())
    if (key == f.key)
      return f.set(p, f.number ? parse_int(value, what, INT32_MIN, INT32_MAX)
                               : parse_int(value, what, 0, 1));
  throw InputError("unknown parameter '" + std::string(key) + "' (known: " + joined(param_keys()) +
                   ")");
}

std::string_view set_param_assignment(Params& p, std::string_view assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw InputError("--set '" + std::string(assignment) +
                     "': expected KEY=VALUE, e.g. --set search_radius=8");
  const std::string_view key = assignment.substr(0, eq);
  set_param(p, key, assignment.substr(eq + 1));
  return key;
}

void require_no_gyro_comp(const Params& p) {
  if (p.gyro_comp)
    throw InputError(
        "--set gyro_comp=1: pxflow takes no gyro rates, so the compensation would have nothing "
        "to add; leave gyro_comp at 0");
}

void validate(const Params& p) {
  auto range = [](const char* name, int v, int lo, int hi) {
    if (v < lo || v > hi)
      throw InputError("parameter " + std::string(name) + " = " + std::to_string(v) +
                       " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
  };
  // T is fixed: the record layout, the 4-byte packing and every kernel assume 8x8 blocks.
  if (p.tile != kTile)
    throw InputError("parameter tile = " + std::to_string(p.tile) + ": only " +
                     std::to_string(kTile) + " is supported (the kernel's 8x8 block)");
  range("search_radius", p.search_radius, kMinSearchRadius, kMaxSearchRadius);
  range("blocks", p.blocks, kMinBlocks, kMaxBlocks);
  range("feature_threshold", p.feature_threshold, 0, kMaxThreshold);
  range("sad_threshold", p.sad_threshold, 0, kMaxThreshold);
  range("min_count", p.min_count, 0, kMaxThreshold);
  range("width", p.width, 1, kMaxFrameSide);
  range("height", p.height, 1, kMaxFrameSide);
  if (std::int64_t{p.width} * p.height > kMaxFramePixels)
    throw InputError("frame " + std::to_string(p.width) + "x" + std::to_string(p.height) +
                     " exceeds the limit of " + std::to_string(kMaxFramePixels) + " pixels");
  // One POI needs lo < hi on each axis: lo = S+1, hi = side-(S+1)-T (SPEC §2).
  const int min_side = min_frame_side(p.search_radius);
  if (p.width < min_side || p.height < min_side)
    throw InputError("frame " + std::to_string(p.width) + "x" + std::to_string(p.height) +
                     " is too small for search_radius " + std::to_string(p.search_radius) +
                     ": each side needs at least " + std::to_string(min_side) + " pixels");
}

}  // namespace pxflow
