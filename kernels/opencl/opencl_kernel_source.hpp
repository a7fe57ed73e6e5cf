// The bytes of kernels/opencl/opencl.cl, embedded by the build (embed_source.cmake).
#pragma once
#include <string_view>

namespace pxflow {

inline constexpr std::string_view kOpenclKernelPath = "kernels/opencl/opencl.cl";

// The kernel source exactly as in the file, compiled at run time by hosts/opencl.
std::string_view opencl_kernel_source();

}  // namespace pxflow
