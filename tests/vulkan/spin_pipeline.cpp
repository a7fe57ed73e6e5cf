#include "spin_pipeline.hpp"

// Generated at build time from tests/vulkan/spin.comp (tests/vulkan/CMakeLists.txt).
#include "spin_spv.h"

namespace pxflow::test {
namespace {

constexpr VkDescriptorType kBindings[] = {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};  // the flag

}  // namespace

SpinPipeline::SpinPipeline(const vk::Context& ctx, VkBuffer flag)
    : pipeline_(ctx, {"spin.comp", k_spin_spirv, kBindings}) {
  pipeline_.write_buffer(0, flag);
}

void SpinPipeline::record(VkCommandBuffer cmd) const {
  pipeline_.bind(cmd);
  // As many groups as every device allows (maxComputeWorkGroupCount is at least 65,535 in x and
  // y): endless even where the driver caps one invocation's loop (spin.comp).
  vkCmdDispatch(cmd, 65535, 65535, 1);
}

}  // namespace pxflow::test
