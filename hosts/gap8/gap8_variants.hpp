// The GAP8 kernel's variants, one table: the rows (gap8-<name>), `pxflow gap8`, the report and
// the tests read it; no other C++ spells a variant. The kernel's build, kernels/gap8's
// CMakeLists.txt, names the same variants to make one embedded ELF each (it knows the sources
// of each); a variant without its ELF is a row that cannot run ("no embedded GAP8 kernel ELF").
#pragma once
#include <span>
#include <string>
#include <string_view>

namespace pxflow {

enum class Gap8Variant { kOriginal, kLocal, kGlobal, kFast };

// How a variant makes its half-pixel values, which is what docs/counting.md charges it.
enum class Gap8HalfPixel {
  kPerPixel,      // every direction interpolated per pixel: 768 per accepted POI
  kLocalPlanes,   // planes h, g, d over the matched block and its border: 300 per accepted POI
  kGlobalPlanes,  // planes h, g, d of the whole next frame: 3 per frame pixel
};

struct Gap8VariantInfo {
  Gap8Variant id;
  const char* name;     // the ELF's name; the row is "gap8-" + name
  const char* summary;  // what it is, for humans
  bool in_paper;        // one of the ISCAS 2022 paper's three (pxflow gap8 --variant all)
  Gap8HalfPixel half_pixel;
};

std::span<const Gap8VariantInfo> gap8_variants();
const Gap8VariantInfo& gap8_variant(Gap8Variant v);
// The variant called `name`; throws InputError listing the names when there is none.
const Gap8VariantInfo& find_gap8_variant(std::string_view name);
std::string gap8_variant_names();  // "original, local, global, fast"

}  // namespace pxflow
