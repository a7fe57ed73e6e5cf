#include "counting_model.hpp"

#include <cstdint>

namespace pxflow {

OpCounts model_counts(RefVariant v, std::span<const PoiRecord> records, const Params& p,
                      std::size_t pairs) {
  const auto side = static_cast<std::uint64_t>(2 * p.search_radius + 1);
  std::uint64_t searched = 0, accepted = 0;
  for (const PoiRecord& r : records) {
    searched += r.status != kDropped;
    accepted += r.status == kAccepted;
  }
  OpCounts c;
  c.counted = true;
  c.sad_ops = 6 * records.size() + 16 * side * side * searched + 128 * accepted;
  switch (v) {
    case RefVariant::kOriginal:
      c.interpolations = (4 * 64 + 4 * 128) * accepted;  // a diagonal value costs 2
      break;
    case RefVariant::kLocal:
      c.interpolations = 3 * 10 * 10 * accepted;  // planes h, g, d of 10 x 10
      break;
    case RefVariant::kGlobal:
      c.interpolations = std::uint64_t{3} * static_cast<std::uint64_t>(p.width) *
                         static_cast<std::uint64_t>(p.height) * pairs;
      break;
  }
  return c;
}

}  // namespace pxflow
