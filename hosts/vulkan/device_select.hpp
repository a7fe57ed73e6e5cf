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
// integrated GPU, else virtual GPU, else CPU, else other. Otherwise the one rule of
// hosts/core/device_choice.hpp (an enumeration index, or a case-insensitive substring of the
// name), whose InputError names a request that fits no device. Throws BackendError when there
// is no device, when no device can run the kernel, or when the one requested cannot.
std::size_t select_device(const std::vector<DeviceCandidate>& devices, std::string_view request);

}  // namespace pxflow::vk
