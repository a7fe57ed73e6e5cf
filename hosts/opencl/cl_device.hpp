// OpenCL platform and device discovery, and the choice of one device by BackendOptions::device.
#pragma once
#include <string>
#include <vector>

#include "cl_util.hpp"

namespace pxflow::cl {

struct DeviceEntry {
  int index = 0;  // position in list_devices(), what --device N selects
  cl_platform_id platform = nullptr;
  cl_device_id device = nullptr;
  std::string name;           // CL_DEVICE_NAME, e.g. "pthread-skylake-avx512-Intel(R) ..."
  std::string platform_name;  // CL_PLATFORM_NAME, e.g. "Portable Computing Language"
  bool gpu = false;           // CL_DEVICE_TYPE_GPU
  bool cpu = false;           // CL_DEVICE_TYPE_CPU (PoCL's pthread device)
};

// Every device of every platform, platforms in driver order. Empty when no platform is
// installed; throws BackendError when the driver fails otherwise.
std::vector<DeviceEntry> list_devices();

// The device `selector` names: empty picks the first GPU, else the first device; otherwise the
// one rule of hosts/core/device_choice.hpp (an index into `devices`, or a case-insensitive
// substring of the device name), whose InputError names a selector that fits no device.
// Throws BackendError when there is no device at all.
const DeviceEntry& choose_device(const std::vector<DeviceEntry>& devices,
                                 const std::string& selector);

}  // namespace pxflow::cl
