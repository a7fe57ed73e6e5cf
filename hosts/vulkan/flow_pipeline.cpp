#include "flow_pipeline.hpp"

#include <algorithm>
#include <cstdint>

#include "vk_error.hpp"

namespace pxflow::vk {
namespace {

// 64 invocations: a multiple of every common subgroup size, small enough for any device (Vulkan
// guarantees at least 128 per work-group).
constexpr std::uint32_t kPreferredLocalSize = 64;

// Binding 0, the frames: a uniform texel buffer (R32_UINT), because lavapipe turns a texel fetch
// with per-invocation addresses into one vector gather, but a storage-buffer read into a
// per-lane, bounds-checked scalar loop (docs/vulkan.md). Binding 1, the records, and binding 2,
// the shader faults (kernels/vulkan/shader_checks.glsl): storage buffers. Both builds of flow.comp
// share this layout: the production build declares no binding 2, which Vulkan allows.
constexpr VkDescriptorType kBindingTypes[] = {VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER,
                                              VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                              VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};

std::uint32_t local_size_for(const Context& ctx) {
  const auto& limits = ctx.properties().limits;
  return std::min({kPreferredLocalSize, limits.maxComputeWorkGroupSize[0],
                   limits.maxComputeWorkGroupInvocations});
}

}  // namespace

FlowPipeline::FlowPipeline(const Context& ctx, int search_radius,
                           std::span<const std::uint32_t> spirv)
    : ctx_(&ctx),
      local_size_(local_size_for(ctx)),
      // constant_id 0 = local_size_x, constant_id 1 = S.
      constants_{static_cast<std::int32_t>(local_size_), search_radius},
      pipeline_(ctx, {"flow.comp", spirv, kBindingTypes, sizeof(FlowPushConstants), constants_}) {}

FlowPipeline::~FlowPipeline() {
  // A spinning shader may still read the view: leaked with the context.
  if (frames_view_ && !ctx_->abandoned())
    vkDestroyBufferView(ctx_->device(), frames_view_, nullptr);
}

void FlowPipeline::bind_buffers(VkBuffer frames, VkBuffer records, VkDeviceSize records_offset,
                                VkBuffer faults) {
  const VkDevice device = ctx_->device();
  if (frames_view_) vkDestroyBufferView(device, frames_view_, nullptr);
  frames_view_ = VK_NULL_HANDLE;
  auto view = zeroed<VkBufferViewCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO);
  view.buffer = frames;
  view.format = VK_FORMAT_R32_UINT;  // one texel = one word of 4 pixels
  view.range = VK_WHOLE_SIZE;
  check(vkCreateBufferView(device, &view, nullptr, &frames_view_), "vkCreateBufferView");
  pipeline_.write_texel_view(0, frames_view_);
  pipeline_.write_buffer(1, records, records_offset);
  pipeline_.write_buffer(2, faults);
}

void FlowPipeline::bind(VkCommandBuffer cmd) const { pipeline_.bind(cmd); }

void FlowPipeline::push(VkCommandBuffer cmd, const FlowPushConstants& pc) const {
  pipeline_.push(cmd, &pc, sizeof(pc));
}

}  // namespace pxflow::vk
