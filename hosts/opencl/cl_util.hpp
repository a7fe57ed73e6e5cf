// Small helpers over the OpenCL C API: error names, checked calls that throw BackendError, and
// owning handles that release their object.
#pragma once
// CL_TARGET_OPENCL_VERSION=120 comes from the build (hosts/opencl/CMakeLists.txt).
#include <CL/cl.h>

#include <chrono>
#include <memory>
#include <string>
#include <type_traits>

namespace pxflow::cl {

// "CL_OUT_OF_RESOURCES" for -5, "CL error -1234" for a code it does not know.
std::string error_name(cl_int code);

// Throws BackendError("opencl: <what> failed: <error name> (<code>)") unless code is CL_SUCCESS.
void check(cl_int code, const std::string& what);

struct Release {
  void operator()(cl_context h) const { clReleaseContext(h); }
  void operator()(cl_command_queue h) const { clReleaseCommandQueue(h); }
  void operator()(cl_program h) const { clReleaseProgram(h); }
  void operator()(cl_kernel h) const { clReleaseKernel(h); }
  void operator()(cl_mem h) const { clReleaseMemObject(h); }
  void operator()(cl_event h) const { clReleaseEvent(h); }
};

// An owning OpenCL handle: Owned<cl_mem>, Owned<cl_kernel>, ...
template <class Handle>
using Owned = std::unique_ptr<std::remove_pointer_t<Handle>, Release>;

// A string-valued device or platform property.
std::string device_string(cl_device_id device, cl_device_info what);
std::string platform_string(cl_platform_id platform, cl_platform_info what);

// A fixed-size device property (cl_ulong, size_t, cl_bool, ...).
template <class T>
T device_value(cl_device_id device, cl_device_info what) {
  T value{};
  check(clGetDeviceInfo(device, what, sizeof value, &value, nullptr), "clGetDeviceInfo");
  return value;
}

// Nanoseconds between the START and END of a profiled command.
cl_ulong event_nanoseconds(cl_event event);

// Waits for `event` to complete or fail, at most `allowance`, and returns its
// CL_EVENT_COMMAND_EXECUTION_STATUS: CL_COMPLETE, a negative error, or CL_QUEUED, CL_SUBMITTED
// or CL_RUNNING when the allowance ran out first. A blocking wait (clWaitForEvents, clFinish)
// could never be given up on a kernel that does not end; this one sleeps on a condition variable
// that the event's completion callback wakes, so a fast kernel costs no polling latency, and asks
// the status every 50 ms for a runtime that runs commands only when called (Oclgrind). The
// command must have been flushed.
cl_int wait_for_event(cl_event event, std::chrono::duration<double> allowance);

}  // namespace pxflow::cl
