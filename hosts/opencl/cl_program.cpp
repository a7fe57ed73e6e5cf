#include "cl_program.hpp"

#include <map>
#include <mutex>

#include "errors.hpp"
#include "opencl_kernel_source.hpp"
#include "params.hpp"

namespace pxflow::cl {
namespace {

std::string build_log(cl_program program, cl_device_id device) {
  std::size_t size = 0;
  if (clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, 0, nullptr, &size) != CL_SUCCESS)
    return "(no build log)";
  std::string log(size, '\0');
  clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, size, log.data(), nullptr);
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log.empty() ? "(empty build log)" : log;
}

}  // namespace

Owned<cl_context> create_context(const DeviceEntry& device) {
  const cl_context_properties props[] = {
      CL_CONTEXT_PLATFORM, reinterpret_cast<cl_context_properties>(device.platform), 0};
  cl_int err = CL_SUCCESS;
  Owned<cl_context> context{clCreateContext(props, 1, &device.device, nullptr, nullptr, &err)};
  check(err, "clCreateContext on '" + device.name + "'");
  return context;
}

Owned<cl_program> build_program(cl_context context, const DeviceEntry& device,
                                std::string_view source, const std::string& options) {
  const char* text = source.data();
  const std::size_t length = source.size();
  cl_int err = CL_SUCCESS;
  Owned<cl_program> program{clCreateProgramWithSource(context, 1, &text, &length, &err)};
  check(err, "clCreateProgramWithSource");
  err = clBuildProgram(program.get(), 1, &device.device, options.c_str(), nullptr, nullptr);
  if (err != CL_SUCCESS)
    throw BackendError("opencl: building " + std::string(kOpenclKernelPath) + " failed on '" +
                       device.name + "': " + error_name(err) + "; device build log:\n" +
                       build_log(program.get(), device.device));
  return program;
}

std::string kernel_options() { return "-DPXFLOW_MAX_RADIUS=" + std::to_string(kMaxSearchRadius); }

std::shared_ptr<const DeviceProgram> device_program(const DeviceEntry& device) {
  // Never destroyed: releasing driver objects from static destructors can run after the
  // driver itself has been torn down at exit.
  static auto* cache = new std::map<cl_device_id, std::shared_ptr<const DeviceProgram>>();
  static auto* mutex = new std::mutex();
  std::lock_guard lock(*mutex);
  if (auto hit = cache->find(device.device); hit != cache->end()) return hit->second;
  auto built = std::make_shared<DeviceProgram>();
  built->device = device;
  built->context = create_context(device);
  built->program =
      build_program(built->context.get(), device, opencl_kernel_source(), kernel_options());
  cache->emplace(device.device, built);
  return built;
}

}  // namespace pxflow::cl
