// The `vulkan` registry row.
#include <vulkan/vulkan.h>

#include "backend.hpp"
#include "context.hpp"
#include "errors.hpp"
#include "vulkan_backend.hpp"

namespace pxflow {
namespace {

// Empty when a Vulkan device that can run the kernel is present. Only the instance and the
// device list are consulted: building the pipeline (which lavapipe JIT-compiles) is left to
// create(), whose BackendError carries the reason if it fails.
std::string probe_vulkan() {
  try {
    const vk::Context ctx({});
    return {};
  } catch (const BackendError& e) {
    std::string why = e.what();
    const std::string prefix = "vulkan: ";
    return why.rfind(prefix, 0) == 0 ? why.substr(prefix.size()) : why;
  }
}

}  // namespace

BackendFamily vulkan_family() {
  BackendRow row;
  row.name = "vulkan";
  row.needs = "a Vulkan 1.2 device with a compute queue (lavapipe: mesa-vulkan-drivers)";
  row.probe = [] {
    static const std::string reason = probe_vulkan();  // the device list does not change
    return reason;
  };
  row.create = [](const BackendOptions& options) -> std::unique_ptr<Backend> {
    VulkanConfig config;
    config.device = options.device;
    return std::make_unique<VulkanBackend>(config);
  };
  row.has_devices = true;
  BackendFamily family{"vulkan", {row}, {}, {}};
  family.environment.push_back(
      {vk::kValidationEnvironment,
       "Not empty and not 0: the vulkan row runs under VK_LAYER_KHRONOS_validation, and any "
       "message of the layer fails the run"});
  return family;
}

}  // namespace pxflow
