// The registry rows of the opencl family: `opencl`, `opencl-item`, `opencl-group`.
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

// One row per kernel layout of opencl.cl, so that `pxflow check` and `bench` run each of them,
// plus `opencl`, the layout chosen for the device (what a user gets; docs/opencl.md says why
// both layouts ship).
BackendFamily opencl_family() {
  struct Layout {
    const char* name;
    OpenclLayout layout;
    const char* needs;
  };
  static constexpr Layout kLayouts[] = {
      {"opencl", OpenclLayout::kAuto,
       "an OpenCL 1.2 device (here PoCL: pocl-opencl-icd); the layout chosen for it"},
      {"opencl-item", OpenclLayout::kItemPerPoi,
       "an OpenCL 1.2 device; kernel flow_item_per_poi (a work-item per POI, CPU default)"},
      {"opencl-group", OpenclLayout::kGroupPerPoi,
       "an OpenCL 1.2 device; kernel flow_group_per_poi (a work-group per POI, GPU default)"},
  };
  BackendFamily family{"opencl", {}, {}, {}};
  for (const Layout& l : kLayouts) {
    BackendRow row;
    row.name = l.name;
    row.needs = l.needs;
    row.probe = probe;
    row.create = [layout = l.layout](const BackendOptions& options) -> std::unique_ptr<Backend> {
      return std::make_unique<OpenclBackend>(options, OpenclTuning{layout, 0, 0});
    };
    row.has_devices = true;
    family.rows.push_back(std::move(row));
  }
  return family;
}

}  // namespace pxflow
