#include "context.hpp"

#include <cstdlib>
#include <cstring>
#include <optional>

#include "device_wait.hpp"
#include "driver_pin.hpp"
#include "vk_error.hpp"

namespace pxflow::vk {
namespace {

// SPIR-V 1.5 from `glslangValidator --target-env vulkan1.2` needs a Vulkan 1.2 device.
constexpr std::uint32_t kApiVersion = VK_API_VERSION_1_2;

std::optional<std::uint32_t> compute_queue_family(VkPhysicalDevice pd) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(pd, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(pd, &count, families.data());
  for (std::uint32_t i = 0; i < count; ++i)
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) return i;
  return std::nullopt;
}

std::vector<VkPhysicalDevice> physical_devices(VkInstance instance) {
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
  devices.resize(count);
  return devices;
}

bool layer_available(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const auto& layer : layers)
    if (std::strcmp(layer.layerName, name) == 0) return true;
  return false;
}

bool validation_requested_by_env() {
  const char* value = std::getenv(kValidationEnvironment);
  return value && *value && std::strcmp(value, "0") != 0;
}

}  // namespace

std::vector<DeviceCandidate> list_devices(VkInstance instance) {
  std::vector<DeviceCandidate> list;
  for (VkPhysicalDevice pd : physical_devices(instance)) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(pd, &props);
    DeviceCandidate c{props.deviceName, props.deviceType, {}};
    if (props.apiVersion < kApiVersion)
      c.unusable = "Vulkan " + std::to_string(VK_API_VERSION_MAJOR(props.apiVersion)) + "." +
                   std::to_string(VK_API_VERSION_MINOR(props.apiVersion)) + " < 1.2";
    else if (!compute_queue_family(pd))
      c.unusable = "no compute queue";
    list.push_back(std::move(c));
  }
  return list;
}

Context::Context(const ContextOptions& options) {
  try {
    create_instance(options.validation || validation_requested_by_env());
    pick_device(options.device);
    create_device();
  } catch (...) {
    release();  // a throwing constructor runs no destructor: free what was created
    throw;
  }
}

Context::~Context() {
  if (!abandoned_) release();
}

void Context::abandon() {
  abandoned_ = true;
  note_abandoned_device();
}

void Context::release() {
  if (device_) vkDestroyDevice(device_, nullptr);
  device_ = VK_NULL_HANDLE;
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
  instance_ = VK_NULL_HANDLE;
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::on_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* self) {
  auto* ctx = static_cast<Context*>(self);
  std::lock_guard lock(ctx->messages_mutex_);
  ctx->messages_.push_back(data->pMessage ? data->pMessage : "(no message text)");
  return VK_FALSE;  // never abort the call: the caller decides what a message means
}

void Context::create_instance(bool validation) {
  auto app = zeroed<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.pApplicationName = "pxflow";
  app.apiVersion = kApiVersion;
  auto info = zeroed<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  info.pApplicationInfo = &app;
  auto messenger = zeroed<VkDebugUtilsMessengerCreateInfoEXT>(
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
  // Warnings and errors of every type. Info is left out: the layer announces itself with an
  // info-level "validation" message ("Khronos Validation Layer Active") that is not a finding.
  messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger.pfnUserCallback = &Context::on_message;
  messenger.pUserData = this;
  const char* layer = kValidationLayer;
  const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  if (validation) {
    if (!layer_available(kValidationLayer))
      fail(std::string(kValidationLayer) + " is not installed (install vulkan-validationlayers)");
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &extension;
    info.pNext = &messenger;  // also catches messages from vkCreateInstance itself
  }
  const std::set<std::string> mapped = loaded_objects();
  const VkResult r = vkCreateInstance(&info, nullptr, &instance_);
  pin_objects_loaded_since(mapped);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
    fail("no Vulkan driver found (install mesa-vulkan-drivers for lavapipe)");
  check(r, "vkCreateInstance");
  if (validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) fail("vkCreateDebugUtilsMessengerEXT is not available");
    check(create(instance_, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
  }
}

void Context::pick_device(const std::string& request) {
  const auto candidates = list_devices(instance_);
  const std::size_t index = select_device(candidates, request);
  physical_ = physical_devices(instance_)[index];
  vkGetPhysicalDeviceProperties(physical_, &properties_);
  queue_family_ = *compute_queue_family(physical_);
}

void Context::create_device() {
  const float priority = 1.0f;
  auto queue = zeroed<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
  queue.queueFamilyIndex = queue_family_;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  auto info = zeroed<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  check(vkCreateDevice(physical_, &info, nullptr, &device_), "vkCreateDevice");
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, families.data());
  timestamp_bits_ = families[queue_family_].timestampValidBits;
}

std::vector<std::string> Context::messages() const {
  std::lock_guard lock(messages_mutex_);
  return messages_;
}

void Context::clear_messages() {
  std::lock_guard lock(messages_mutex_);
  messages_.clear();
}

}  // namespace pxflow::vk
