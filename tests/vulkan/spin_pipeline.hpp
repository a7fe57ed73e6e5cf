// The pipeline of tests/vulkan/spin.comp, a shader that never ends, on one storage buffer (its
// first word must be 0). For the hang tests: a dispatch of it keeps a CommandRunner's fence
// unsignalled for ever. Like the backend's objects, it leaks itself once the context was
// abandoned (the shader may still run).
#pragma once
#include <vulkan/vulkan.h>

#include "vulkan/context.hpp"

namespace pxflow::test {

class SpinPipeline {
 public:
  SpinPipeline(const vk::Context& ctx, VkBuffer flag);  // throws BackendError
  ~SpinPipeline();
  SpinPipeline(const SpinPipeline&) = delete;
  SpinPipeline& operator=(const SpinPipeline&) = delete;

  // Records binding the pipeline and the buffer, and one dispatch of 65,535 x 65,535 groups.
  void record(VkCommandBuffer cmd) const;

 private:
  void release();

  const vk::Context* ctx_;
  VkShaderModule shader_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace pxflow::test
