// A context on one device with the kernel program built for it. Built once per device and
// process, then shared by every backend instance on that device: PoCL compiles with LLVM at
// build time, and paying that once keeps tests and probes quick.
#pragma once
#include <memory>
#include <string>
#include <string_view>

#include "cl_device.hpp"

namespace pxflow::cl {

struct DeviceProgram {
  DeviceEntry device;
  Owned<cl_context> context;
  Owned<cl_program> program;
};

Owned<cl_context> create_context(const DeviceEntry& device);

// Builds `source` for `device`. On failure throws BackendError: one summary line naming the
// file and the device, then the device's build log.
Owned<cl_program> build_program(cl_context context, const DeviceEntry& device,
                                std::string_view source, const std::string& options = {});

// The build options the embedded kernels/opencl/opencl.cl needs: SPEC's largest radius
// (-DPXFLOW_MAX_RADIUS=31, from reference/params.hpp), which sizes the item kernel's private
// arrays. device_program builds with them; so must anything else that builds that source.
std::string kernel_options();

// The shared DeviceProgram of `device` with the embedded kernels/opencl/opencl.cl, built on
// first use. A failed build is not cached: the next call tries again.
std::shared_ptr<const DeviceProgram> device_program(const DeviceEntry& device);

}  // namespace pxflow::cl
