#include "gap8_variants.hpp"

#include <stdexcept>

#include "errors.hpp"

namespace pxflow {
namespace {

constexpr Gap8VariantInfo kVariants[] = {
    {Gap8Variant::kOriginal, "original",
     "the firmware's compute_flow ported unchanged (the paper's original)", true,
     Gap8HalfPixel::kPerPixel},
    {Gap8Variant::kLocal, "local", "half-pixel planes per accepted POI (the paper's local)", true,
     Gap8HalfPixel::kLocalPlanes},
    {Gap8Variant::kGlobal, "global",
     "half-pixel planes of the whole frame before matching (the paper's global)", true,
     Gap8HalfPixel::kGlobalPlanes},
    {Gap8Variant::kFast, "fast", "beyond the paper: the fastest bit-exact kernel we could write",
     false, Gap8HalfPixel::kPerPixel},
};

}  // namespace

std::span<const Gap8VariantInfo> gap8_variants() { return kVariants; }

const Gap8VariantInfo& gap8_variant(Gap8Variant v) {
  for (const auto& info : kVariants)
    if (info.id == v) return info;
  throw std::logic_error("gap8: a variant missing from gap8_variants()");
}

std::string gap8_variant_names() {
  std::string s;
  for (const auto& info : kVariants) s += (s.empty() ? "" : ", ") + std::string(info.name);
  return s;
}

const Gap8VariantInfo& find_gap8_variant(std::string_view name) {
  for (const auto& info : kVariants)
    if (name == info.name) return info;
  throw InputError("unknown GAP8 variant '" + std::string(name) +
                   "' (known: " + gap8_variant_names() + ")");
}

}  // namespace pxflow
