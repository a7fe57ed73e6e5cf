#include "batch_plan.hpp"

#include <algorithm>

#include "grid.hpp"

namespace pxflow::vk {

BatchLayout batch_layout(const Params& p) {
  BatchLayout b;
  const std::uint64_t pixels = std::uint64_t(p.width) * std::uint64_t(p.height);
  b.words_per_frame = static_cast<std::uint32_t>((pixels + 3) / 4 + 1);
  b.pair_bytes = 2ull * b.words_per_frame * 4;
  b.pois_per_pair = poi_count(p);
  b.record_bytes_per_pair = b.pois_per_pair * 32ull;
  const std::uint64_t side = 2ull * p.search_radius + 1;
  b.work_per_pair = b.pois_per_pair * side * side * 64;
  return b;
}

std::size_t pairs_per_chunk(const BatchLayout& layout, const ChunkLimits& limits) {
  if (layout.pair_bytes > limits.max_buffer_bytes ||
      layout.record_bytes_per_pair > limits.max_buffer_bytes)
    return 0;
  std::uint64_t n = limits.max_buffer_bytes / layout.pair_bytes;
  if (layout.record_bytes_per_pair > 0)
    n = std::min(n, limits.max_buffer_bytes / layout.record_bytes_per_pair);
  if (layout.work_per_pair > 0)
    n = std::min(n, std::max<std::uint64_t>(1, limits.max_work / layout.work_per_pair));
  return static_cast<std::size_t>(n);
}

}  // namespace pxflow::vk
