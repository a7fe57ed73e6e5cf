#include "cl_device.hpp"

#include <algorithm>

#include "device_choice.hpp"
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

const DeviceEntry& choose_device(const std::vector<DeviceEntry>& devices,
                                 const std::string& selector) {
  if (devices.empty())
    throw BackendError("opencl: no OpenCL platform or device found (install pocl-opencl-icd)");
  if (selector.empty()) {
    auto gpu = std::find_if(devices.begin(), devices.end(), [](const auto& d) { return d.gpu; });
    return gpu != devices.end() ? *gpu : devices.front();
  }
  std::vector<DeviceLabel> labels;
  for (const auto& d : devices) labels.push_back({d.name, d.platform_name});
  return devices[device_index_for("opencl", labels, selector)];
}

}  // namespace pxflow::cl
