#include "device_select.hpp"

#include "errors.hpp"

#include <algorithm>
#include <cctype>

#include "vk_error.hpp"

namespace pxflow::vk {
namespace {

// Lower rank = preferred when the user names no device.
int preference_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 3;
    default:
      return 4;
  }
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::size_t checked(const std::vector<DeviceCandidate>& devices, std::size_t index,
                    std::string_view request) {
  if (!devices[index].unusable.empty())
    fail("device '" + std::string(request) + "' (" + devices[index].name +
         ") cannot run the kernel: " + devices[index].unusable);
  return index;
}

}  // namespace

std::string_view device_type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete gpu";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual gpu";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "cpu";
    default:
      return "other";
  }
}

std::string describe_devices(const std::vector<DeviceCandidate>& devices) {
  std::string text;
  for (std::size_t i = 0; i < devices.size(); ++i) {
    text += (i ? ", " : "") + std::to_string(i) + " '" + devices[i].name + "' (" +
            std::string(device_type_name(devices[i].type)) + ")";
  }
  return text.empty() ? "none" : text;
}

std::size_t select_device(const std::vector<DeviceCandidate>& devices, std::string_view request) {
  if (devices.empty()) fail("no Vulkan device found (install mesa-vulkan-drivers for lavapipe)");
  if (request.empty()) {
    std::size_t best = devices.size();
    for (std::size_t i = 0; i < devices.size(); ++i) {
      if (!devices[i].unusable.empty()) continue;
      if (best == devices.size() ||
          preference_rank(devices[i].type) < preference_rank(devices[best].type))
        best = i;
    }
    if (best == devices.size())
      fail("no Vulkan device can run the kernel: " + devices[0].name + ": " + devices[0].unusable);
    return best;
  }
  if (all_digits(request)) {
    const std::size_t index =
        request.size() > 9 ? devices.size() : std::stoul(std::string(request));
    if (index >= devices.size())
      // A --device that names nothing is the user's input, not a driver failure: exit 2.
      throw InputError("vulkan: device index " + std::string(request) +
                       " is out of range (devices: " + describe_devices(devices) + ")");
    return checked(devices, index, request);
  }
  for (std::size_t i = 0; i < devices.size(); ++i)
    if (lower(devices[i].name).find(lower(request)) != std::string::npos)
      return checked(devices, i, request);
  throw InputError("vulkan: no Vulkan device name contains '" + std::string(request) +
                   "' (devices: " + describe_devices(devices) + ")");
}

}  // namespace pxflow::vk
