// The registry rows, one function per backend family. Adding a backend: write its row function
// in its own hosts/ folder, declare it here, and add one line to registry.cpp.
#pragma once
#include <vector>

#include "backend.hpp"

namespace pxflow {

std::vector<BackendRow> reference_rows();  // ref-original, ref-local, ref-global
std::vector<BackendRow> cpu_rows();        // hosts/cpu: swar and the native SIMD variants
std::vector<BackendRow> opencl_rows();     // hosts/opencl
std::vector<BackendRow> vulkan_rows();     // hosts/vulkan
std::vector<BackendRow> gap8_rows();       // hosts/gap8: the kernel on the cluster model

}  // namespace pxflow
