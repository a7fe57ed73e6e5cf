// Turning Vulkan result codes into the project's one-line BackendError, and a struct helper.
#pragma once
#include <vulkan/vulkan.h>

#include <string>
#include <string_view>

namespace pxflow::vk {

// Throws BackendError("vulkan: <what> failed: <result name>") unless r is VK_SUCCESS.
void check(VkResult r, std::string_view what);

// A Vulkan info struct with every member zero but its sType (no -Wmissing-field-initializers).
template <class T>
T zeroed(VkStructureType type) {
  T value{};
  value.sType = type;
  return value;
}

// Throws BackendError("vulkan: <message>").
[[noreturn]] void fail(std::string_view message);

}  // namespace pxflow::vk
