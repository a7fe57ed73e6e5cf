// The two builds of kernels/vulkan/flow.comp (kernels/vulkan/CMakeLists.txt): their names, their
// embedded SPIR-V, and what the backend says when their records differ.
#pragma once
#include <cstdint>
#include <span>
#include <string>

#include "frame.hpp"
#include "params.hpp"
#include "record.hpp"
#include "vulkan_backend.hpp"

namespace pxflow::vk {

// "checked shader" or "production shader" (`build` is one of the two).
std::string shader_name(VulkanShaders build);

// The build's SPIR-V as embedded at build time.
std::span<const std::uint32_t> built_in_spirv(VulkanShaders build);

// The failure for records of the two builds over `pairs` that differ (they must): where they
// first do, and which build's record there differs from ref-original's, computed here for that
// pair alone.
std::string shaders_disagree(std::span<const FramePair> pairs, const Params& p,
                             std::span<const PoiRecord> checked,
                             std::span<const PoiRecord> production);

}  // namespace pxflow::vk
