#include "device_select.hpp"

#include "device_choice.hpp"
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

std::size_t default_device(const std::vector<DeviceCandidate>& devices) {
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

}  // namespace

std::size_t select_device(const std::vector<DeviceCandidate>& devices, std::string_view request) {
  if (devices.empty()) fail("no Vulkan device found (install mesa-vulkan-drivers for lavapipe)");
  if (request.empty()) return default_device(devices);
  std::vector<DeviceLabel> labels;
  for (const auto& d : devices) labels.push_back({d.name, std::string(device_type_name(d.type))});
  const std::size_t index = device_index_for("vulkan", labels, request);
  // A device the user named that exists but cannot run the kernel is the driver's limit, not a
  // typo: a BackendError, as when no device can run it.
  if (!devices[index].unusable.empty())
    fail("device '" + std::string(request) + "' (" + devices[index].name +
         ") cannot run the kernel: " + devices[index].unusable);
  return index;
}

}  // namespace pxflow::vk
