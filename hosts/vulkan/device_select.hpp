// Choosing a physical device (BackendOptions::device): pure logic, testable without a device.
#pragma once
#include <vulkan/vulkan.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace pxflow::vk {

// What selection needs to know about one physical device, in enumeration order.
struct DeviceCandidate {
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  std::string unusable;  // empty when it can run the kernel, else why not (no compute queue, ...)
};

// The index of the device to use. `request` empty: the first usable discrete GPU, else
// integrated GPU, else virtual GPU, else CPU, else other. All digits: that enumeration index.
// Otherwise: the first device whose name contains `request` (case-insensitive). Throws
// BackendError naming the request and listing the devices when nothing fits.
std::size_t select_device(const std::vector<DeviceCandidate>& devices, std::string_view request);

// "0 'llvmpipe (LLVM 15.0.6, 256 bits)' (cpu), 1 ..." for error messages.
std::string describe_devices(const std::vector<DeviceCandidate>& devices);

std::string_view device_type_name(VkPhysicalDeviceType type);

}  // namespace pxflow::vk
