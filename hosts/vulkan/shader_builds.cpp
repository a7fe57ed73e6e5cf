#include "shader_builds.hpp"

#include <cstring>
#include <vector>

#include "grid.hpp"
#include "kernel.hpp"

// Generated at build time from kernels/vulkan/flow.comp (kernels/vulkan/CMakeLists.txt).
#include "flow_checked_spv.h"
#include "flow_spv.h"

namespace pxflow::vk {
namespace {

bool same(const PoiRecord& a, const PoiRecord& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

std::string shader_name(VulkanShaders build) {
  return build == VulkanShaders::checked ? "checked shader" : "production shader";
}

std::span<const std::uint32_t> built_in_spirv(VulkanShaders build) {
  if (build == VulkanShaders::checked) return k_flow_checked_spirv;
  return k_flow_spirv;
}

std::string shaders_disagree(std::span<const FramePair> pairs, const Params& p,
                             std::span<const PoiRecord> checked,
                             std::span<const PoiRecord> production) {
  std::size_t first = 0;
  while (first < checked.size() && same(checked[first], production[first])) ++first;
  const std::size_t per = poi_count(p);
  const std::size_t pair = first / per;
  std::vector<PoiRecord> want(per);
  OpCounts counts;
  reference_flow(RefVariant::kOriginal, pairs[pair], p, want, counts);
  const PoiRecord& ref = want[first % per];
  const bool checked_right = same(checked[first], ref);
  const bool production_right = same(production[first], ref);
  const std::string wrong = checked_right      ? "the production shader's record differs"
                            : production_right ? "the checked shader's record differs"
                                               : "both shaders' records differ";
  return "the checked and production shaders wrote different records, first for pair " +
         std::to_string(pair) + " POI " + std::to_string(first % per) +
         " (x=" + std::to_string(ref.x) + ",y=" + std::to_string(ref.y) + "): " + wrong +
         " from ref-original's there (kernels/vulkan/shader_checks.glsl)";
}

}  // namespace pxflow::vk
