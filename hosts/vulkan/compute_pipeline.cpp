#include "compute_pipeline.hpp"

#include "vk_error.hpp"

namespace pxflow::vk {

ComputePipeline::ComputePipeline(const Context& ctx, const ComputePipelineSpec& spec)
    : ctx_(&ctx), device_(ctx.device()), types_(spec.types.begin(), spec.types.end()) {
  try {
    create_layouts(spec);
    create_pipeline(spec);
    create_descriptor_set();
  } catch (...) {
    release();
    throw;
  }
}

ComputePipeline::~ComputePipeline() {
  if (!ctx_->abandoned()) release();  // a spinning shader may still use it: leak it
}

void ComputePipeline::release() {
  if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);  // frees set_ too
  if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
  if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
  if (set_layout_) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
  if (shader_) vkDestroyShaderModule(device_, shader_, nullptr);
  pool_ = VK_NULL_HANDLE;
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  set_layout_ = VK_NULL_HANDLE;
  shader_ = VK_NULL_HANDLE;
}

void ComputePipeline::create_layouts(const ComputePipelineSpec& spec) {
  std::vector<VkDescriptorSetLayoutBinding> bindings(types_.size());
  for (std::uint32_t b = 0; b < bindings.size(); ++b)
    bindings[b] = {b, types_[b], 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  auto set_info =
      zeroed<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  set_info.bindingCount = static_cast<std::uint32_t>(bindings.size());
  set_info.pBindings = bindings.data();
  check(vkCreateDescriptorSetLayout(device_, &set_info, nullptr, &set_layout_),
        "vkCreateDescriptorSetLayout");
  const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, spec.push_constant_bytes};
  auto info = zeroed<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  info.setLayoutCount = 1;
  info.pSetLayouts = &set_layout_;
  info.pushConstantRangeCount = spec.push_constant_bytes > 0 ? 1 : 0;
  info.pPushConstantRanges = &range;
  check(vkCreatePipelineLayout(device_, &info, nullptr, &layout_), "vkCreatePipelineLayout");
}

void ComputePipeline::create_pipeline(const ComputePipelineSpec& spec) {
  auto module = zeroed<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
  module.codeSize = spec.spirv.size_bytes();
  module.pCode = spec.spirv.data();
  check(vkCreateShaderModule(device_, &module, nullptr, &shader_), "vkCreateShaderModule");
  std::vector<VkSpecializationMapEntry> entries;
  for (std::uint32_t i = 0; i < spec.specialization.size(); ++i)
    entries.push_back(
        {i, static_cast<std::uint32_t>(i * sizeof(std::int32_t)), sizeof(std::int32_t)});
  const VkSpecializationInfo constants{static_cast<std::uint32_t>(entries.size()), entries.data(),
                                       spec.specialization.size_bytes(),
                                       spec.specialization.data()};
  auto info = zeroed<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = shader_;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = entries.empty() ? nullptr : &constants;
  info.layout = layout_;
  check(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
        "vkCreateComputePipelines (" + spec.name + ")");
}

void ComputePipeline::create_descriptor_set() {
  std::vector<VkDescriptorPoolSize> sizes;  // one per binding: a type may repeat
  for (const VkDescriptorType t : types_) sizes.push_back({t, 1});
  auto pool = zeroed<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pool.maxSets = 1;
  pool.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  pool.pPoolSizes = sizes.data();
  check(vkCreateDescriptorPool(device_, &pool, nullptr, &pool_), "vkCreateDescriptorPool");
  auto alloc = zeroed<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &set_layout_;
  check(vkAllocateDescriptorSets(device_, &alloc, &set_), "vkAllocateDescriptorSets");
}

VkWriteDescriptorSet ComputePipeline::write_of(std::uint32_t b) const {
  auto write = zeroed<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
  write.dstSet = set_;
  write.dstBinding = b;
  write.descriptorCount = 1;
  write.descriptorType = types_.at(b);
  return write;
}

void ComputePipeline::write_buffer(std::uint32_t b, VkBuffer buffer, VkDeviceSize offset) {
  const VkDescriptorBufferInfo info{buffer, offset, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write = write_of(b);
  write.pBufferInfo = &info;
  vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
}

void ComputePipeline::write_texel_view(std::uint32_t b, VkBufferView view) {
  VkWriteDescriptorSet write = write_of(b);
  write.pTexelBufferView = &view;
  vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
}

void ComputePipeline::bind(VkCommandBuffer cmd) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
}

void ComputePipeline::push(VkCommandBuffer cmd, const void* data, std::uint32_t bytes) const {
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, bytes, data);
}

}  // namespace pxflow::vk
