// One command buffer, one fence and a two-slot timestamp query pool: record, submit, wait as long
// as the work submitted allows (hosts/core/device_wait.hpp), read the device time. Reused for
// every chunk of every batch.
#pragma once
#include <vulkan/vulkan.h>

#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include "context.hpp"
#include "device_wait.hpp"

namespace pxflow::vk {

class CommandRunner {
 public:
  explicit CommandRunner(Context& ctx);  // throws BackendError
  ~CommandRunner();
  CommandRunner(const CommandRunner&) = delete;
  CommandRunner& operator=(const CommandRunner&) = delete;

  // Records `body` between two timestamps (when the queue has them), submits, and waits up to
  // wait_allowance(work). Throws BackendError on any failure; after a lost device the runner
  // refuses further work, after a wait that fired it also abandons the context (the command
  // buffer may still run: Context::abandon).
  void run(const std::function<void(VkCommandBuffer)>& body, const DeviceWork& work);

  // Records `body` (a dispatch of no work that makes the driver compile a pipeline, which
  // lavapipe does at the first dispatch), submits it and waits as long as a build may take
  // (kBuildSeconds), in slices that notice a stop signal: a compile is build time, never part of a
  // wait sized by the work of a dispatch. `what` names the build ("the checked shader at S=31")
  // in the failure line. Throws BackendError (a build that never ends abandons the context, as
  // run() does) or Interrupted.
  void run_build(const std::function<void(VkCommandBuffer)>& body, const std::string& what);

  // Throws BackendError when an earlier timeout or lost device made the runner refuse work.
  // Callers check before touching buffers that a pending command buffer may still use.
  void ensure_usable() const;

  // Device time between the two timestamps of the last run(), in nanoseconds; empty when the
  // queue has no timestamps.
  std::optional<double> last_device_ns() const { return last_ns_; }

 private:
  void submit(const std::function<void(VkCommandBuffer)>& body);
  void record(const std::function<void(VkCommandBuffer)>& body);
  void wait(const DeviceWork& work);
  void wait_build(const std::string& what);
  [[noreturn]] void give_up(const std::string& line);
  void read_timestamps();
  void release();

  Context* ctx_;
  VkDevice device_;
  VkQueue queue_;
  std::uint32_t timestamp_bits_;
  float timestamp_period_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkQueryPool queries_ = VK_NULL_HANDLE;
  std::optional<double> last_ns_;
  std::string broken_;  // why the runner refuses work, after a timeout or a lost device
};

}  // namespace pxflow::vk
