// The reference keeps its readable C++ (SPEC.md as code); the freestanding kernels take the spec
// core (spec/include/pxflow_spec). Here the compiler holds the two to one contract: every type,
// code, table and limit the core defines is asserted equal to the reference's. The grid and the
// estimate, which are code rather than constants, are compared by tests/spec/test_spec_core.cpp.
#include <cstddef>
#include <cstdint>
#include <iterator>

#include "estimate.hpp"
#include "params.hpp"
#include "poi_steps.hpp"
#include "pxflow_spec/spec.h"
#include "record.hpp"

namespace pxflow {
namespace {

// SPEC §4's record: the same size and every field at the same offset, so PoiRecord and
// pxflow_poi_record convert by memcpy (hosts/dut's codec, the GAP8 kernel's L2 records).
static_assert(sizeof(PoiRecord) == sizeof(pxflow_poi_record));
static_assert(sizeof(PoiRecord) == PXFLOW_RECORD_BYTES);
#define PXFLOW_SAME_FIELD(f) \
  static_assert(offsetof(PoiRecord, f) == offsetof(pxflow_poi_record, f), #f)
PXFLOW_SAME_FIELD(x);
PXFLOW_SAME_FIELD(y);
PXFLOW_SAME_FIELD(status);
PXFLOW_SAME_FIELD(pad0);
PXFLOW_SAME_FIELD(feature);
PXFLOW_SAME_FIELD(dx);
PXFLOW_SAME_FIELD(dy);
PXFLOW_SAME_FIELD(sad);
PXFLOW_SAME_FIELD(dir);
PXFLOW_SAME_FIELD(pad1);
PXFLOW_SAME_FIELD(sub);
PXFLOW_SAME_FIELD(hx);
PXFLOW_SAME_FIELD(hy);
#undef PXFLOW_SAME_FIELD
static_assert(offsetof(PoiRecord, feature) == PXFLOW_RECORD_AT_FEATURE);
static_assert(offsetof(PoiRecord, hx) == PXFLOW_RECORD_AT_HX);

// Status and direction codes.
static_assert(kDropped == PXFLOW_STATUS_DROPPED && kRejected == PXFLOW_STATUS_REJECTED &&
              kAccepted == PXFLOW_STATUS_ACCEPTED);
static_assert(kDirNone == PXFLOW_DIR_NONE && kDirNone == PXFLOW_DIRECTIONS);

// SPEC §3's half-pixel step table.
constexpr int kCoreStepX[] = PXFLOW_STEP_X_TABLE;
constexpr int kCoreStepY[] = PXFLOW_STEP_Y_TABLE;
constexpr bool same_steps() {
  static_assert(std::size(kCoreStepX) == std::size(ref::kStepX) &&
                std::size(kCoreStepY) == std::size(ref::kStepY));
  for (std::size_t k = 0; k < std::size(ref::kStepX); ++k)
    if (kCoreStepX[k] != ref::kStepX[k] || kCoreStepY[k] != ref::kStepY[k]) return false;
  return true;
}
static_assert(same_steps());

// SPEC §1's limits and the histogram size of SPEC §5.
static_assert(kTile == PXFLOW_TILE);
static_assert(kMinSearchRadius == PXFLOW_MIN_RADIUS && kMaxSearchRadius == PXFLOW_MAX_RADIUS);
static_assert(kMinBlocks == PXFLOW_MIN_BLOCKS && kMaxBlocks == PXFLOW_MAX_BLOCKS);
static_assert(kMaxThreshold == PXFLOW_MAX_THRESHOLD);
static_assert(kMaxFrameSide == PXFLOW_MAX_FRAME_SIDE);
static_assert(kMaxFramePixels == PXFLOW_MAX_FRAME_PIXELS);
static_assert(2 * (2 * kMaxSearchRadius + 1) + 1 == PXFLOW_MAX_BINS);

// The parameter block has one u32 per Params field, in Params's order.
static_assert(sizeof(pxflow_param_block) == PXFLOW_PARAM_FIELDS * sizeof(std::uint32_t));

}  // namespace
}  // namespace pxflow
