// A storage buffer in host-visible, host-coherent memory, mapped for its whole life. On lavapipe
// and integrated GPUs this is the device's own memory; on a discrete GPU it is slower than
// device-local memory but needs no staging copies (docs/vulkan.md).
#pragma once
#include <vulkan/vulkan.h>

#include <cstddef>

#include "context.hpp"

namespace pxflow::vk {

class HostBuffer {
 public:
  HostBuffer(const Context& ctx, VkDeviceSize size);  // throws BackendError
  ~HostBuffer();
  HostBuffer(const HostBuffer&) = delete;
  HostBuffer& operator=(const HostBuffer&) = delete;

  VkBuffer buffer() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  std::byte* data() const { return static_cast<std::byte*>(mapped_); }

 private:
  void release();

  const Context* ctx_;
  VkDevice device_;
  VkDeviceSize size_;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;
};

}  // namespace pxflow::vk
