// The compute pipeline of kernels/vulkan/flow.comp for one search radius (a ComputePipeline:
// descriptor set of frames, records and shader faults; push constants), and the texel buffer
// view through which it reads the frames. S is a specialization constant (the driver unrolls the
// search loops for it), so a backend keeps one pipeline per radius it has seen. When the driver
// compiles it varies: at vkCreateComputePipelines, or (lavapipe) at its first dispatch, which is
// why the backend warms each new pipeline with a dispatch of no work (docs/vulkan.md, "Building a
// pipeline").
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

#include "compute_pipeline.hpp"
#include "context.hpp"

namespace pxflow::vk {

// Mirrors `Problem` in flow.comp, word for word.
struct FlowPushConstants {
  std::uint32_t width;
  std::uint32_t feature_threshold;
  std::uint32_t sad_threshold;
  std::uint32_t grid_x0;
  std::uint32_t grid_step_x;
  std::uint32_t grid_nx;
  std::uint32_t grid_y0;
  std::uint32_t grid_step_y;
  std::uint32_t pois_per_pair;
  std::uint32_t words_per_frame;
  std::uint32_t first_item;
  std::uint32_t item_count;
};

class FlowPipeline {
 public:
  // `spirv`: the shader's code, a build of kernels/vulkan/flow.comp (shader_builds.hpp) or a
  // test's copy with its interface. Throws BackendError.
  FlowPipeline(const Context& ctx, int search_radius, std::span<const std::uint32_t> spirv);
  ~FlowPipeline();
  FlowPipeline(const FlowPipeline&) = delete;
  FlowPipeline& operator=(const FlowPipeline&) = delete;

  // Invocations per work-group (the shader's local_size_x), within the device's limits.
  std::uint32_t local_size() const { return local_size_; }

  // Points the descriptor set at the buffers (frames through a texel buffer view made here; the
  // records from `records_offset`, past the guard before them, to the buffer's end; the
  // shader faults, kernels/vulkan/shader_checks.glsl, which the production build leaves unused);
  // call when they change, never while in use.
  void bind_buffers(VkBuffer frames, VkBuffer records, VkDeviceSize records_offset,
                    VkBuffer faults);

  // Records binding the pipeline and its descriptor set into `cmd`.
  void bind(VkCommandBuffer cmd) const;
  void push(VkCommandBuffer cmd, const FlowPushConstants& pc) const;

  // Whether a dispatch has run it (the backend's warm-up, VulkanBackend::prepare): then the
  // driver has compiled it, whenever it does.
  bool warmed() const { return warmed_; }
  void set_warmed() { warmed_ = true; }

 private:
  const Context* ctx_;
  std::uint32_t local_size_;
  std::int32_t constants_[2];
  ComputePipeline pipeline_;
  VkBufferView frames_view_ = VK_NULL_HANDLE;  // the frames buffer as R32_UINT texels
  bool warmed_ = false;
};

}  // namespace pxflow::vk
