// The `opencl` registry row.
#include <sstream>

#include "backend.hpp"
#include "opencl_backend.hpp"

namespace pxflow {
namespace {

// One line for `pxflow backends`: the error's first line, plus the first line of a build log
// that mentions an error.
std::string one_line(const std::string& message) {
  std::istringstream lines(message);
  std::string first, line;
  std::getline(lines, first);
  while (std::getline(lines, line))
    if (line.find("error") != std::string::npos) return first + " " + line;
  return first;
}

std::string probe() {
  try {
    const auto devices = cl::list_devices();
    if (devices.empty()) return "no OpenCL platform or device found (install pocl-opencl-icd)";
    cl::device_program(cl::choose_device(devices, ""));  // compiles the kernel once
    return {};
  } catch (const std::exception& e) {
    return one_line(e.what());
  }
}

}  // namespace

BackendFamily opencl_family() {
  BackendRow row{"opencl", "an OpenCL 1.2 device (here PoCL: pocl-opencl-icd)", probe,
                 [](const BackendOptions& options) { return std::make_unique<OpenclBackend>(options); }};
  row.has_devices = true;
  return {"opencl", {row}, {}, {}};
}

}  // namespace pxflow
