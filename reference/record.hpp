// The per-POI record every backend produces (SPEC §4) and the frame estimate (SPEC §5).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pxflow {

enum PoiStatus : std::uint8_t {
  kDropped = 0,   // feature < FT
  kRejected = 1,  // best integer SAD >= VT
  kAccepted = 2,
};

inline constexpr std::uint8_t kDirNone = 8;  // the integer match won the half-pixel vote

// 32 bytes, natural alignment, padding spelled out so that it is zeroed like any field and two
// records compare with memcmp. Device kernels write the same layout as 8 little-endian words.
struct PoiRecord {
  std::uint16_t x;
  std::uint16_t y;
  std::uint8_t status;
  std::uint8_t pad0;  // always 0
  std::uint16_t feature;
  std::int8_t dx;
  std::int8_t dy;
  std::uint16_t sad;
  std::uint8_t dir;
  std::uint8_t pad1;  // always 0
  std::uint16_t sub[8];
  std::int8_t hx;
  std::int8_t hy;
};
static_assert(sizeof(PoiRecord) == 32);
static_assert(offsetof(PoiRecord, feature) == 6);
static_assert(offsetof(PoiRecord, sad) == 10);
static_assert(offsetof(PoiRecord, sub) == 14);
static_assert(offsetof(PoiRecord, hx) == 30);

// Work a backend reports for a batch. `counted` is false for backends that do not count.
struct OpCounts {
  bool counted = false;
  std::uint64_t sad_ops = 0;         // 4-byte SAD operations (USAD8/USADA8 equivalents)
  std::uint64_t interpolations = 0;  // half-pixel values computed, counted as in docs/counting.md

  OpCounts& operator+=(const OpCounts& o) {
    counted = counted || o.counted;
    sad_ops += o.sad_ops;
    interpolations += o.interpolations;
    return *this;
  }
};

struct FrameResult {
  float flow_x = 0.0f;               // pixels per frame, content motion to the right is positive
  float flow_y = 0.0f;               // content motion downward is positive
  int quality = 0;                   // 0..255
  int meancount = 0;                 // accepted POIs
  std::vector<std::uint16_t> histx;  // nbins = 2*(2S+1)+1
  std::vector<std::uint16_t> histy;
};

}  // namespace pxflow
