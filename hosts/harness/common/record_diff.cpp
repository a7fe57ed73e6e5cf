#include "record_diff.hpp"

#include <cstring>

namespace pxflow {

bool untouched(const PoiRecord& r, unsigned char sentinel) {
  const auto* b = reinterpret_cast<const unsigned char*>(&r);
  for (std::size_t i = 0; i < sizeof r; ++i)
    if (b[i] != sentinel) return false;
  return true;
}

std::optional<FieldDiff> first_difference(const PoiRecord& e, const PoiRecord& g) {
  if (std::memcmp(&e, &g, sizeof e) == 0) return std::nullopt;
  auto diff = [](std::string name, long a, long b) -> std::optional<FieldDiff> {
    if (a == b) return std::nullopt;
    return FieldDiff{std::move(name), std::to_string(a), std::to_string(b)};
  };
  // SPEC §4's order, then the padding.
  const std::pair<const char*, std::pair<long, long>> fields[] = {
      {"x", {e.x, g.x}},
      {"y", {e.y, g.y}},
      {"status", {e.status, g.status}},
      {"feature", {e.feature, g.feature}},
      {"dx", {e.dx, g.dx}},
      {"dy", {e.dy, g.dy}},
      {"sad", {e.sad, g.sad}},
      {"dir", {e.dir, g.dir}},
  };
  for (const auto& [name, v] : fields)
    if (auto d = diff(name, v.first, v.second)) return d;
  for (int k = 0; k < 8; ++k)
    if (auto d = diff("sub[" + std::to_string(k) + "]", e.sub[k], g.sub[k])) return d;
  if (auto d = diff("hx", e.hx, g.hx)) return d;
  if (auto d = diff("hy", e.hy, g.hy)) return d;
  if (auto d = diff("pad0", e.pad0, g.pad0)) return d;
  return diff("pad1", e.pad1, g.pad1);
}

}  // namespace pxflow
