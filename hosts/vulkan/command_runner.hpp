// One command buffer, one fence and a two-slot timestamp query pool: record, submit, wait with
// a timeout, read the device time. Reused for every chunk of every batch.
#pragma once
#include <vulkan/vulkan.h>

#include <chrono>
#include <functional>
#include <optional>

#include "context.hpp"

namespace pxflow::vk {

class CommandRunner {
 public:
  explicit CommandRunner(const Context& ctx);  // throws BackendError
  ~CommandRunner();
  CommandRunner(const CommandRunner&) = delete;
  CommandRunner& operator=(const CommandRunner&) = delete;

  // Records `body` between two timestamps (when the queue has them), submits, and waits up to
  // `timeout`. Throws BackendError on any failure; after a timeout or a lost device the runner
  // refuses further work (the command buffer may still be pending).
  void run(const std::function<void(VkCommandBuffer)>& body, std::chrono::milliseconds timeout);

  // Throws BackendError when an earlier timeout or lost device made the runner refuse work.
  // Callers check before touching buffers that a pending command buffer may still use.
  void ensure_usable() const;

  // Device time between the two timestamps of the last run(), in nanoseconds; empty when the
  // queue has no timestamps.
  std::optional<double> last_device_ns() const { return last_ns_; }

 private:
  void record(const std::function<void(VkCommandBuffer)>& body);
  void wait(std::chrono::milliseconds timeout);
  void read_timestamps();
  void release();

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
