// The GAP8 registry rows: one per kernel variant of gap8_variants(), on the 8-core cluster model.
#include "backend.hpp"
#include "errors.hpp"
#include "gap8_backend.hpp"
#include "gap8_kernel_elf.hpp"
#include "gap8_variants.hpp"

namespace pxflow {
namespace {

// The reference variant whose counting rules a variant's half-pixel scheme follows.
RefVariant counts_like(Gap8HalfPixel h) {
  switch (h) {
    case Gap8HalfPixel::kPerPixel:
      return RefVariant::kOriginal;
    case Gap8HalfPixel::kLocalPlanes:
      return RefVariant::kLocal;
    case Gap8HalfPixel::kGlobalPlanes:
      return RefVariant::kGlobal;
  }
  return RefVariant::kOriginal;
}

BackendRow gap8_row(const Gap8VariantInfo& v) {
  BackendRow row{std::string("gap8-") + v.name,
                 "nothing (the GAP8 cluster cycle model is built in; 8 cores, " +
                     std::to_string(static_cast<int>(kGap8ClockHz / 1e6)) + " MHz)",
                 [name = v.name]() -> std::string {
                   return gap8_kernel_elf(name).empty() ? "no embedded GAP8 kernel ELF" : "";
                 },
                 [id = v.id](const BackendOptions& o) -> std::unique_ptr<Backend> {
                   return std::make_unique<Gap8Backend>(id, gap8_host::RunOptions{}, o.threads);
                 }};
  row.counts_like = counts_like(v.half_pixel);
  return row;
}

}  // namespace

BackendFamily gap8_family() {
  BackendFamily family{"gap8", {}, {}, {}};
  for (const Gap8VariantInfo& v : gap8_variants()) family.rows.push_back(gap8_row(v));
  family.environment.push_back({"TMPDIR",
                                "Where the gap8 rows write the kernel ELF for libelf to read "
                                "(removed at once); default /tmp"});
  return family;
}

}  // namespace pxflow
