#include "flow_pipeline.hpp"

#include <algorithm>
#include <cstdint>
#include <iterator>

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
constexpr std::uint32_t kBindings = std::size(kBindingTypes);

}  // namespace

FlowPipeline::FlowPipeline(const Context& ctx, int search_radius,
                           std::span<const std::uint32_t> spirv)
    : ctx_(&ctx), device_(ctx.device()), search_radius_(search_radius) {
  const auto& limits = ctx.properties().limits;
  local_size_ = std::min({kPreferredLocalSize, limits.maxComputeWorkGroupSize[0],
                          limits.maxComputeWorkGroupInvocations});
  try {
    create_layouts();
    create_pipeline(spirv);
    create_descriptor_set();
  } catch (...) {
    release();
    throw;
  }
}

FlowPipeline::~FlowPipeline() {
  if (!ctx_->abandoned()) release();  // a spinning shader may still use it: leak it
}

void FlowPipeline::release() {
  if (frames_view_) vkDestroyBufferView(device_, frames_view_, nullptr);
  if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);  // frees set_ too
  if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
  if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
  if (set_layout_) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
  if (shader_) vkDestroyShaderModule(device_, shader_, nullptr);
  frames_view_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  set_layout_ = VK_NULL_HANDLE;
  shader_ = VK_NULL_HANDLE;
}

void FlowPipeline::create_layouts() {
  VkDescriptorSetLayoutBinding bindings[kBindings] = {};
  for (std::uint32_t b = 0; b < kBindings; ++b) {
    bindings[b].binding = b;
    bindings[b].descriptorType = kBindingTypes[b];
    bindings[b].descriptorCount = 1;
    bindings[b].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  auto set_info =
      zeroed<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  set_info.bindingCount = kBindings;
  set_info.pBindings = bindings;
  check(vkCreateDescriptorSetLayout(device_, &set_info, nullptr, &set_layout_),
        "vkCreateDescriptorSetLayout");
  VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(FlowPushConstants)};
  auto info = zeroed<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  info.setLayoutCount = 1;
  info.pSetLayouts = &set_layout_;
  info.pushConstantRangeCount = 1;
  info.pPushConstantRanges = &range;
  check(vkCreatePipelineLayout(device_, &info, nullptr, &layout_), "vkCreatePipelineLayout");
}

void FlowPipeline::create_pipeline(std::span<const std::uint32_t> spirv) {
  auto module = zeroed<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
  module.codeSize = spirv.size_bytes();
  module.pCode = spirv.data();
  check(vkCreateShaderModule(device_, &module, nullptr, &shader_), "vkCreateShaderModule");
  // constant_id 0 = local_size_x, constant_id 1 = S.
  const std::int32_t values[2] = {static_cast<std::int32_t>(local_size_), search_radius_};
  const VkSpecializationMapEntry entries[2] = {{0, 0, sizeof(std::int32_t)},
                                               {1, sizeof(std::int32_t), sizeof(std::int32_t)}};
  const VkSpecializationInfo spec{2, entries, sizeof(values), values};
  auto info = zeroed<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = shader_;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = &spec;
  info.layout = layout_;
  check(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
        "vkCreateComputePipelines (flow.comp)");
}

void FlowPipeline::create_descriptor_set() {
  VkDescriptorPoolSize sizes[kBindings];  // one per binding: a type may repeat
  for (std::uint32_t b = 0; b < kBindings; ++b) sizes[b] = {kBindingTypes[b], 1};
  auto pool = zeroed<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pool.maxSets = 1;
  pool.poolSizeCount = kBindings;
  pool.pPoolSizes = sizes;
  check(vkCreateDescriptorPool(device_, &pool, nullptr, &pool_), "vkCreateDescriptorPool");
  auto alloc = zeroed<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &set_layout_;
  check(vkAllocateDescriptorSets(device_, &alloc, &set_), "vkAllocateDescriptorSets");
}

void FlowPipeline::bind_buffers(VkBuffer frames, VkBuffer records, VkDeviceSize records_offset,
                                VkBuffer faults) {
  if (frames_view_) vkDestroyBufferView(device_, frames_view_, nullptr);
  frames_view_ = VK_NULL_HANDLE;
  auto view = zeroed<VkBufferViewCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO);
  view.buffer = frames;
  view.format = VK_FORMAT_R32_UINT;  // one texel = one word of 4 pixels
  view.range = VK_WHOLE_SIZE;
  check(vkCreateBufferView(device_, &view, nullptr, &frames_view_), "vkCreateBufferView");
  const VkDescriptorBufferInfo records_info{records, records_offset, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo faults_info{faults, 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet writes[kBindings] = {};
  for (std::uint32_t b = 0; b < kBindings; ++b) {
    writes[b].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[b].dstSet = set_;
    writes[b].dstBinding = b;
    writes[b].descriptorCount = 1;
    writes[b].descriptorType = kBindingTypes[b];
  }
  writes[0].pTexelBufferView = &frames_view_;
  writes[1].pBufferInfo = &records_info;
  writes[2].pBufferInfo = &faults_info;
  vkUpdateDescriptorSets(device_, kBindings, writes, 0, nullptr);
}

void FlowPipeline::bind(VkCommandBuffer cmd) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
}

void FlowPipeline::push(VkCommandBuffer cmd, const FlowPushConstants& pc) const {
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(pc), &pc);
}

}  // namespace pxflow::vk
