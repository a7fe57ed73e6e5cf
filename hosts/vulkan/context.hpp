// The Vulkan instance, the chosen physical device, a logical device and its compute queue.
// Owns them for the lifetime of one backend object; every failure is a BackendError.
#pragma once
#include <vulkan/vulkan.h>

#include <atomic>
#include <mutex>
#include <string>
#include <vector>

#include "device_select.hpp"

namespace pxflow::vk {

struct ContextOptions {
  std::string device;       // BackendOptions::device: index or name substring; empty = preferred
  bool validation = false;  // enable VK_LAYER_KHRONOS_validation and collect its messages
};

// The instance layer that validation enables.
inline constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// The variable that asks for validation when it is set and not "0".
inline constexpr const char* kValidationEnvironment = "PXFLOW_VULKAN_VALIDATION";

class Context {
 public:
  explicit Context(const ContextOptions& options);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical_device() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  std::uint32_t queue_family() const { return queue_family_; }
  std::uint32_t timestamp_valid_bits() const { return timestamp_bits_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }

  // Validation-layer messages received so far: every warning and error, of any type
  // (validation, performance, general). Always empty without validation.
  std::vector<std::string> messages() const;
  void clear_messages();

  // Gives the device up while work may still run on it (a wait that fired): from now on nothing
  // made from this context is destroyed, the device and instance included, since that would wait
  // for the work forever. The objects are leaked on purpose (docs/vulkan.md, "Waiting on a
  // device") and the process ends without joining the driver's threads
  // (exit_now_if_device_abandoned).
  void abandon();
  bool abandoned() const { return abandoned_; }

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT type,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* self);
  void create_instance(bool validation);
  void pick_device(const std::string& request);
  void create_device();
  void release();

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queue_family_ = 0;
  std::uint32_t timestamp_bits_ = 0;
  VkPhysicalDeviceProperties properties_{};
  mutable std::mutex messages_mutex_;
  std::vector<std::string> messages_;
  std::atomic<bool> abandoned_{false};
};

// The devices of `instance` as selection candidates, with the reason each one cannot be used.
std::vector<DeviceCandidate> list_devices(VkInstance instance);

}  // namespace pxflow::vk
