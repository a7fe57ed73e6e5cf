#include "host_buffer.hpp"

#include "vk_error.hpp"

namespace pxflow::vk {
namespace {

std::uint32_t host_memory_type(VkPhysicalDevice pd, std::uint32_t allowed) {
  VkPhysicalDeviceMemoryProperties props;
  vkGetPhysicalDeviceMemoryProperties(pd, &props);
  const VkMemoryPropertyFlags need =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  for (std::uint32_t i = 0; i < props.memoryTypeCount; ++i)
    if ((allowed & (1u << i)) && (props.memoryTypes[i].propertyFlags & need) == need) return i;
  fail("the device offers no host-visible coherent memory for storage buffers");
}

}  // namespace

HostBuffer::HostBuffer(const Context& ctx, VkDeviceSize size)
    : ctx_(&ctx), device_(ctx.device()), size_(size) {
  try {
    auto info = zeroed<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    info.size = size;
    // Frames are read through a uniform texel buffer view (flow_pipeline.cpp), records written
    // as a storage buffer.
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    check(vkCreateBuffer(device_, &info, nullptr, &buffer_), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, buffer_, &req);
    auto alloc = zeroed<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = host_memory_type(ctx.physical_device(), req.memoryTypeBits);
    check(vkAllocateMemory(device_, &alloc, nullptr, &memory_),
          "vkAllocateMemory of " + std::to_string(req.size) + " bytes");
    check(vkBindBufferMemory(device_, buffer_, memory_, 0), "vkBindBufferMemory");
    check(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
  } catch (...) {
    release();
    throw;
  }
}

HostBuffer::~HostBuffer() {
  if (!ctx_->abandoned()) release();  // a spinning shader may still write here: leak it
}

void HostBuffer::release() {
  if (mapped_) vkUnmapMemory(device_, memory_);
  if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);
  mapped_ = nullptr;
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
}

}  // namespace pxflow::vk
