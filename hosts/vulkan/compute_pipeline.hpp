// A compute pipeline with one descriptor set, one descriptor per binding: the shader module, the
// set's layout, the pipeline layout (with push constants), the pipeline, and the set from a pool
// of its own, made in that order and released in reverse. Every shader pxflow runs is one:
// FlowPipeline (kernels/vulkan/flow.comp) and the hang test's spinning shader
// (tests/vulkan/spin.comp), so the Vulkan calls that make a pipeline exist once.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "context.hpp"

namespace pxflow::vk {

struct ComputePipelineSpec {
  std::string name;                         // "flow.comp": named by a failed call's error
  std::span<const std::uint32_t> spirv;     // entry point "main"
  std::span<const VkDescriptorType> types;  // binding b holds one descriptor of types[b]
  std::uint32_t push_constant_bytes = 0;
  std::span<const std::int32_t> specialization{};  // constant_id i = specialization[i]
};

class ComputePipeline {
 public:
  ComputePipeline(const Context& ctx, const ComputePipelineSpec& spec);  // throws BackendError
  // Leaks what it holds once the context was abandoned: a shader given up on may still use it.
  ~ComputePipeline();
  ComputePipeline(const ComputePipeline&) = delete;
  ComputePipeline& operator=(const ComputePipeline&) = delete;

  // Point binding `b` at a buffer from `offset` to its end, or at a texel buffer view; call
  // before recording, never while a command buffer using the set is pending.
  void write_buffer(std::uint32_t b, VkBuffer buffer, VkDeviceSize offset = 0);
  void write_texel_view(std::uint32_t b, VkBufferView view);

  // Records binding the pipeline and its descriptor set into `cmd`.
  void bind(VkCommandBuffer cmd) const;
  // Records push constants: `bytes` from offset 0.
  void push(VkCommandBuffer cmd, const void* data, std::uint32_t bytes) const;

 private:
  void create_layouts(const ComputePipelineSpec& spec);
  void create_pipeline(const ComputePipelineSpec& spec);
  void create_descriptor_set();
  VkWriteDescriptorSet write_of(std::uint32_t b) const;
  void release();

  const Context* ctx_;
  VkDevice device_;
  std::vector<VkDescriptorType> types_;
  VkShaderModule shader_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace pxflow::vk
