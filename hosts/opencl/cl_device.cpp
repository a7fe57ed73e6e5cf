#include "cl_device.hpp"

#include <algorithm>
#include <cctype>

#include "errors.hpp"

namespace pxflow::cl {
namespace {

constexpr cl_int kPlatformNotFound = -1001;  // CL_PLATFORM_NOT_FOUND_KHR (ICD loader)

std::vector<cl_platform_id> platforms() {
  cl_uint count = 0;
  const cl_int err = clGetPlatformIDs(0, nullptr, &count);
  if (err == kPlatformNotFound || (err == CL_SUCCESS && count == 0)) return {};
  check(err, "clGetPlatformIDs");
  std::vector<cl_platform_id> ids(count);
  check(clGetPlatformIDs(count, ids.data(), nullptr), "clGetPlatformIDs");
  return ids;
}

std::vector<cl_device_id> devices_of(cl_platform_id platform) {
  cl_uint count = 0;
  const cl_int err = clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, 0, nullptr, &count);
  if (err == CL_DEVICE_NOT_FOUND || (err == CL_SUCCESS && count == 0)) return {};
  check(err, "clGetDeviceIDs");
  std::vector<cl_device_id> ids(count);
  check(clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, count, ids.data(), nullptr), "clGetDeviceIDs");
  return ids;
}

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool is_index(const std::string& s) {
  return !s.empty() && s.size() < 9 &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

}  // namespace

std::vector<DeviceEntry> list_devices() {
  std::vector<DeviceEntry> out;
  for (cl_platform_id platform : platforms()) {
    const std::string platform_name = platform_string(platform, CL_PLATFORM_NAME);
    for (cl_device_id device : devices_of(platform)) {
      DeviceEntry e;
      e.index = static_cast<int>(out.size());
      e.platform = platform;
      e.device = device;
      e.name = device_string(device, CL_DEVICE_NAME);
      e.platform_name = platform_name;
      const auto type = device_value<cl_device_type>(device, CL_DEVICE_TYPE);
      e.gpu = (type & CL_DEVICE_TYPE_GPU) != 0;
      e.cpu = (type & CL_DEVICE_TYPE_CPU) != 0;
      out.push_back(std::move(e));
    }
  }
  return out;
}

std::string describe(const std::vector<DeviceEntry>& devices) {
  std::string text;
  for (const auto& d : devices)
    text += (text.empty() ? "" : ", ") + std::to_string(d.index) + " = " + d.name + " (" +
            d.platform_name + ")";
  return text;
}

const DeviceEntry& choose_device(const std::vector<DeviceEntry>& devices,
                                 const std::string& selector) {
  if (devices.empty())
    throw BackendError("opencl: no OpenCL platform or device found (install pocl-opencl-icd)");
  const std::string known = " (devices: " + describe(devices) + ")";
  if (selector.empty()) {
    auto gpu = std::find_if(devices.begin(), devices.end(), [](const auto& d) { return d.gpu; });
    return gpu != devices.end() ? *gpu : devices.front();
  }
  if (is_index(selector)) {
    const std::size_t index = std::stoul(selector);
    if (index >= devices.size())
      throw InputError("opencl: device index " + selector + " is out of range" + known);
    return devices[index];
  }
  const std::string wanted = lowercase(selector);
  for (const auto& d : devices)
    if (lowercase(d.name).find(wanted) != std::string::npos) return d;
  throw InputError("opencl: no device name contains '" + selector + "'" + known);
}

}  // namespace pxflow::cl
