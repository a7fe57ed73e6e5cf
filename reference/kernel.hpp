// The scalar reference kernel: the executable form of SPEC §3, in the three variants of the
// paper (SPEC §6). All three produce identical records; they differ in how half-pixel values are
// made and therefore in how many interpolations they count.
#pragma once
#include <span>
#include <string_view>

#include "frame.hpp"
#include "params.hpp"
#include "record.hpp"

namespace pxflow {

enum class RefVariant {
  kOriginal,  // per POI, per direction, per pixel (diagonals charged 2)
  kLocal,     // per POI, three 10x10 planes h, g, d around the matched block
  kGlobal,    // per frame, three full-frame planes h, g, d before any matching
};

// Every variant, in the order above.
inline constexpr RefVariant kRefVariants[] = {RefVariant::kOriginal, RefVariant::kLocal,
                                              RefVariant::kGlobal};

// The registry name of a variant: "ref-original", "ref-local", "ref-global".
std::string_view ref_variant_name(RefVariant v);

// Runs one frame pair. `out` must hold exactly poi_count(p) records; every byte of each record
// is written. `p` must be valid (validate()) and match the frames' size. Counts are added to
// `counts` (which is marked counted).
void reference_flow(RefVariant v, const FramePair& pair, const Params& p, std::span<PoiRecord> out,
                    OpCounts& counts);

}  // namespace pxflow
