// The `vulkan` backend: kernels/vulkan/flow.comp on a Vulkan device (lavapipe here). The class
// is public so that tests and the benchmark can reach what the Backend interface does not
// offer: validation, chunk limits, the device time of the last run.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "backend.hpp"

namespace pxflow {

namespace vk {
class Context;
class FlowPipeline;
class CommandRunner;
class HostBuffer;
}  // namespace vk

// Which builds of kernels/vulkan/flow.comp run() runs (kernels/vulkan/shader_checks.glsl).
enum class VulkanShaders {
  checked,     // with the shader checks: a fault fails the run
  production,  // without them: what `pxflow bench` times
  // The checked build, then the production build on the same pairs: the records are the checked
  // shader's, and the production shader's must equal them, or the run fails naming the one that
  // differs from ref-original (pxflow check, flow and bench's check).
  both,
};

struct VulkanConfig {
  std::string device;       // index or name substring (BackendOptions::device); empty = preferred
  bool validation = false;  // Khronos validation layer on; any message fails the run
  // Upper bound of each storage buffer, below the device's maxStorageBufferRange.
  std::uint64_t max_buffer_bytes = 64ull << 20;
  // Integer-search pixel differences per chunk: keeps each submission well under a second on
  // lavapipe and under GPU watchdogs.
  std::uint64_t max_chunk_work = 1ull << 31;
  std::uint32_t max_groups_per_dispatch = 0;  // 0 = the device's maxComputeWorkGroupCount[0]
  // Tests only: dispatch this many items past the output (with frames for them), a planted
  // overrun the guard after the records must catch.
  std::uint32_t overrun_items = 0;
  // What run() runs until Backend::select_timed() says otherwise.
  VulkanShaders shaders = VulkanShaders::both;
  // Tests only: SPIR-V to run instead of the built-in checked or production build of flow.comp,
  // with the same interface (a planted fault, tests/vulkan/CMakeLists.txt).
  std::vector<std::uint32_t> checked_spirv, production_spirv;
};

class VulkanBackend final : public Backend {
 public:
  // Throws InputError for a config.device that names no device (hosts/core/device_choice.hpp),
  // BackendError when the driver fails.
  explicit VulkanBackend(const VulkanConfig& config);
  ~VulkanBackend() override;

  void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
           OpCounts& counts) override;
  // Builds and warms the pipelines run() runs at p.search_radius (docs/vulkan.md, "Building a
  // pipeline"); run() does it itself for any it lacks.
  void prepare(const Params& p) override;
  std::string unsupported(const Params& p) const override;
  // false: config.shaders; true: the production shader alone (what `pxflow bench` times).
  std::string select_timed(bool timed) override;

  // Device time of the last run(), summed over its chunks of every shader it ran (timestamp
  // queries), in seconds;
  // empty when the queue has no timestamps or no run completed.
  std::optional<double> last_device_seconds() const { return last_device_seconds_; }
  // The same as Backend::DeviceTime, source "vulkan-timestamps", for the benchmark.
  std::optional<DeviceTime> last_device_time() const override;
  // Chunks (submissions) and dispatches of each shader's pass over the last run()'s pairs.
  std::size_t last_chunks() const { return last_chunks_; }
  std::size_t last_dispatches() const { return last_dispatches_; }
  // Seconds spent building pipelines so far (creating each and waiting for its warm-up dispatch,
  // in which lavapipe compiles it): time no run() and no device wait counts.
  double build_seconds() const { return build_seconds_; }
  std::string device_name() const;
  // The device and its driver (VkPhysicalDeviceDriverProperties, core in Vulkan 1.2).
  Description describe() const override;
  std::string device_kind() const override;  // VkPhysicalDeviceType: "cpu", "gpu", "other"
  // Validation-layer messages so far (only with config.validation or PXFLOW_VULKAN_VALIDATION).
  std::vector<std::string> validation_messages() const;

 private:
  std::uint64_t buffer_limit() const;
  // The pipeline of `build` at p.search_radius, created and warmed (a dispatch of no work, waited
  // for as build time) if it was not yet.
  vk::FlowPipeline& ready_pipeline(VulkanShaders build, const Params& p);
  void warm(vk::FlowPipeline& pipeline, VulkanShaders build, const Params& p);
  void ensure_buffers(std::uint64_t frame_bytes, std::uint64_t record_bytes);
  // One build's pass over the pairs, chunk by chunk; returns its device nanoseconds, if timed.
  std::optional<double> run_shader(VulkanShaders build, std::span<const FramePair> pairs,
                                   const Params& p, std::span<PoiRecord> out);
  void run_chunk(vk::FlowPipeline& pipeline, std::span<const FramePair> pairs, const Params& p,
                 std::span<PoiRecord> out);
  void fail_on_validation_messages() const;

  VulkanConfig config_;
  VulkanShaders shaders_;  // what run() runs now
  std::unique_ptr<vk::Context> ctx_;
  // By build (checked or production) and search radius.
  std::map<std::pair<VulkanShaders, int>, std::unique_ptr<vk::FlowPipeline>> pipelines_;
  std::unique_ptr<vk::CommandRunner> runner_;
  std::unique_ptr<vk::HostBuffer> frames_;
  // The records between guard zones (hosts/core/guard_zone.hpp): records_front_ bytes of guard
  // (the device's storage buffer offset alignment), the records, kGuardBytes of guard.
  std::unique_ptr<vk::HostBuffer> records_;
  std::uint64_t records_front_ = 0;
  // Binding 2 of the checked flow.comp: its shader faults (kernels/vulkan/shader_checks.glsl),
  // cleared before each chunk and checked after it (the production build leaves it unused).
  std::unique_ptr<vk::HostBuffer> faults_;
  std::optional<double> last_device_seconds_;
  std::size_t last_chunks_ = 0;
  std::size_t last_dispatches_ = 0;
  double build_seconds_ = 0;
};

}  // namespace pxflow
