// The pipeline of tests/vulkan/spin.comp, a shader that never ends, on one storage buffer (its
// first word must be 0). For the hang tests: a dispatch of it keeps a CommandRunner's fence
// unsignalled for ever. Made by the backend's own ComputePipeline (hosts/vulkan/
// compute_pipeline.hpp), which leaks itself once the context was abandoned (the shader may still
// run).
#pragma once
#include <vulkan/vulkan.h>

#include "vulkan/compute_pipeline.hpp"
#include "vulkan/context.hpp"

namespace pxflow::test {

class SpinPipeline {
 public:
  SpinPipeline(const vk::Context& ctx, VkBuffer flag);  // throws BackendError

  // Records binding the pipeline and the buffer, and one dispatch of 65,535 x 65,535 groups.
  void record(VkCommandBuffer cmd) const;

 private:
  vk::ComputePipeline pipeline_;
};

}  // namespace pxflow::test
