// One rule for --device (BackendOptions::device) in every family whose backends choose among
// devices (OpenCL, Vulkan): a decimal number is an index into the family's device list, which
// must exist; anything else is a case-insensitive substring of a device name, the first match
// wins. Anything that names no device is the user's input error, with the same text in every
// family. What an empty --device picks is the family's own default (GPU first).
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace pxflow {

// A device as the user sees it in listings and chooses it by name.
struct DeviceLabel {
  std::string name;    // matched by a name substring, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string detail;  // shown after the name, e.g. the OpenCL platform or the Vulkan type
};

// The index of the device `request` names; `request` is not empty. Throws InputError
// "<family>: device index <n> is out of range (devices: ...)" for a number (of any length) that
// is not an index of `devices`, and "<family>: no device name contains '<request>' (devices:
// ...)" for a name that matches none.
std::size_t device_index_for(std::string_view family, const std::vector<DeviceLabel>& devices,
                             std::string_view request);

}  // namespace pxflow
