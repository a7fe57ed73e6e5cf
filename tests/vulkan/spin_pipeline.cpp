#include "spin_pipeline.hpp"

#include "vulkan/vk_error.hpp"

// Generated at build time from tests/vulkan/spin.comp (tests/vulkan/CMakeLists.txt).
#include "spin_spv.h"

namespace pxflow::test {

using vk::check;
using vk::zeroed;

SpinPipeline::SpinPipeline(const vk::Context& ctx, VkBuffer flag) : ctx_(&ctx) {
  const VkDevice device = ctx.device();
  try {
    VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                                         VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    auto set_info = zeroed<VkDescriptorSetLayoutCreateInfo>(
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    set_info.bindingCount = 1;
    set_info.pBindings = &binding;
    check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout_),
          "vkCreateDescriptorSetLayout");
    auto info = zeroed<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    info.setLayoutCount = 1;
    info.pSetLayouts = &set_layout_;
    check(vkCreatePipelineLayout(device, &info, nullptr, &layout_), "vkCreatePipelineLayout");
    auto module = zeroed<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    module.codeSize = sizeof(k_spin_spirv);
    module.pCode = k_spin_spirv;
    check(vkCreateShaderModule(device, &module, nullptr, &shader_), "vkCreateShaderModule");
    auto pipe = zeroed<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
    pipe.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    pipe.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipe.stage.module = shader_;
    pipe.stage.pName = "main";
    pipe.layout = layout_;
    check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipe, nullptr, &pipeline_),
          "vkCreateComputePipelines (spin.comp)");
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
    auto pool = zeroed<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    pool.maxSets = 1;
    pool.poolSizeCount = 1;
    pool.pPoolSizes = &size;
    check(vkCreateDescriptorPool(device, &pool, nullptr, &pool_), "vkCreateDescriptorPool");
    auto alloc =
        zeroed<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    alloc.descriptorPool = pool_;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &set_layout_;
    check(vkAllocateDescriptorSets(device, &alloc, &set_), "vkAllocateDescriptorSets");
    const VkDescriptorBufferInfo buffer{flag, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write =
        zeroed<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    write.dstSet = set_;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &buffer;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
  } catch (...) {
    release();
    throw;
  }
}

SpinPipeline::~SpinPipeline() {
  if (!ctx_->abandoned()) release();  // the shader may still run: leaked with the context
}

void SpinPipeline::release() {
  const VkDevice device = ctx_->device();
  if (pool_) vkDestroyDescriptorPool(device, pool_, nullptr);
  if (pipeline_) vkDestroyPipeline(device, pipeline_, nullptr);
  if (layout_) vkDestroyPipelineLayout(device, layout_, nullptr);
  if (set_layout_) vkDestroyDescriptorSetLayout(device, set_layout_, nullptr);
  if (shader_) vkDestroyShaderModule(device, shader_, nullptr);
  pool_ = VK_NULL_HANDLE;
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  set_layout_ = VK_NULL_HANDLE;
  shader_ = VK_NULL_HANDLE;
}

void SpinPipeline::record(VkCommandBuffer cmd) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
  // As many groups as every device allows (maxComputeWorkGroupCount is at least 65,535 in x and
  // y): endless even where the driver caps one invocation's loop (spin.comp).
  vkCmdDispatch(cmd, 65535, 65535, 1);
}

}  // namespace pxflow::test
