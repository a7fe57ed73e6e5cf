#include "cl_util.hpp"

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <vector>

#include "errors.hpp"

namespace pxflow::cl {

std::string error_name(cl_int code) {
  switch (code) {
#define PXFLOW_CL_ERROR(name) \
  case name:                  \
    return #name;
    PXFLOW_CL_ERROR(CL_DEVICE_NOT_FOUND)
    PXFLOW_CL_ERROR(CL_DEVICE_NOT_AVAILABLE)
    PXFLOW_CL_ERROR(CL_COMPILER_NOT_AVAILABLE)
    PXFLOW_CL_ERROR(CL_MEM_OBJECT_ALLOCATION_FAILURE)
    PXFLOW_CL_ERROR(CL_OUT_OF_RESOURCES)
    PXFLOW_CL_ERROR(CL_OUT_OF_HOST_MEMORY)
    PXFLOW_CL_ERROR(CL_PROFILING_INFO_NOT_AVAILABLE)
    PXFLOW_CL_ERROR(CL_BUILD_PROGRAM_FAILURE)
    PXFLOW_CL_ERROR(CL_MAP_FAILURE)
    PXFLOW_CL_ERROR(CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST)
    PXFLOW_CL_ERROR(CL_INVALID_VALUE)
    PXFLOW_CL_ERROR(CL_INVALID_PLATFORM)
    PXFLOW_CL_ERROR(CL_INVALID_DEVICE)
    PXFLOW_CL_ERROR(CL_INVALID_CONTEXT)
    PXFLOW_CL_ERROR(CL_INVALID_COMMAND_QUEUE)
    PXFLOW_CL_ERROR(CL_INVALID_MEM_OBJECT)
    PXFLOW_CL_ERROR(CL_INVALID_BUFFER_SIZE)
    PXFLOW_CL_ERROR(CL_INVALID_PROGRAM)
    PXFLOW_CL_ERROR(CL_INVALID_PROGRAM_EXECUTABLE)
    PXFLOW_CL_ERROR(CL_INVALID_KERNEL_NAME)
    PXFLOW_CL_ERROR(CL_INVALID_KERNEL)
    PXFLOW_CL_ERROR(CL_INVALID_ARG_INDEX)
    PXFLOW_CL_ERROR(CL_INVALID_ARG_VALUE)
    PXFLOW_CL_ERROR(CL_INVALID_ARG_SIZE)
    PXFLOW_CL_ERROR(CL_INVALID_KERNEL_ARGS)
    PXFLOW_CL_ERROR(CL_INVALID_WORK_DIMENSION)
    PXFLOW_CL_ERROR(CL_INVALID_WORK_GROUP_SIZE)
    PXFLOW_CL_ERROR(CL_INVALID_WORK_ITEM_SIZE)
    PXFLOW_CL_ERROR(CL_INVALID_GLOBAL_WORK_SIZE)
    PXFLOW_CL_ERROR(CL_INVALID_EVENT)
    PXFLOW_CL_ERROR(CL_INVALID_OPERATION)
    PXFLOW_CL_ERROR(CL_INVALID_BUILD_OPTIONS)
#undef PXFLOW_CL_ERROR
    case -1001:  // CL_PLATFORM_NOT_FOUND_KHR, from the ICD loader when no driver is installed
      return "CL_PLATFORM_NOT_FOUND_KHR";
    default:
      return "CL error " + std::to_string(code);
  }
}

void check(cl_int code, const std::string& what) {
  if (code != CL_SUCCESS)
    throw BackendError("opencl: " + what + " failed: " + error_name(code) + " (" +
                       std::to_string(code) + ")");
}

namespace {

template <class Query>
std::string query_string(Query&& query, const char* what) {
  std::size_t size = 0;
  check(query(0, nullptr, &size), what);
  std::vector<char> text(size + 1, '\0');
  check(query(size, text.data(), nullptr), what);
  return std::string(text.data());  // drops the driver's terminating NUL
}

}  // namespace

std::string device_string(cl_device_id device, cl_device_info what) {
  return query_string(
      [&](std::size_t n, void* out, std::size_t* size) {
        return clGetDeviceInfo(device, what, n, out, size);
      },
      "clGetDeviceInfo");
}

std::string platform_string(cl_platform_id platform, cl_platform_info what) {
  return query_string(
      [&](std::size_t n, void* out, std::size_t* size) {
        return clGetPlatformInfo(platform, what, n, out, size);
      },
      "clGetPlatformInfo");
}

namespace {

// What the completion callback and the waiting host share. The callback holds a reference of its
// own: after a wait that was given up, it may still come (or never: then it leaks with the device).
struct Completion {
  std::mutex mutex;
  std::condition_variable done_cv;
  bool done = false;
};

void CL_CALLBACK on_complete(cl_event, cl_int, void* user) {
  auto* held = static_cast<std::shared_ptr<Completion>*>(user);
  {
    std::lock_guard lock((*held)->mutex);
    (*held)->done = true;
  }
  (*held)->done_cv.notify_all();
  delete held;
}

}  // namespace

constexpr std::chrono::milliseconds kStatusPoll{50};

cl_int wait_for_event(cl_event event, std::chrono::duration<double> allowance) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(allowance);
  auto completion = std::make_shared<Completion>();
  auto* held = new std::shared_ptr<Completion>(completion);
  // Called once, when the command completes or fails (OpenCL 1.2, clSetEventCallback).
  const cl_int err = clSetEventCallback(event, CL_COMPLETE, on_complete, held);
  if (err != CL_SUCCESS) delete held;
  check(err, "clSetEventCallback");
  // The callback ends the wait at once; the status is also asked every 50 ms, since a runtime
  // may run its commands only when the host calls into it (Oclgrind does): its callback comes
  // from the query, never from the wait alone.
  cl_int status = CL_QUEUED;
  for (;;) {
    {
      std::unique_lock lock(completion->mutex);
      const Clock::time_point turn = std::min(deadline, Clock::now() + kStatusPoll);
      if (completion->done_cv.wait_until(lock, turn, [&] { return completion->done; })) break;
    }
    check(clGetEventInfo(event, CL_EVENT_COMMAND_EXECUTION_STATUS, sizeof status, &status, nullptr),
          "clGetEventInfo");
    if (status <= CL_COMPLETE || Clock::now() >= deadline) return status;
  }
  check(clGetEventInfo(event, CL_EVENT_COMMAND_EXECUTION_STATUS, sizeof status, &status, nullptr),
        "clGetEventInfo");
  return status;
}

cl_ulong event_nanoseconds(cl_event event) {
  cl_ulong start = 0, end = 0;
  check(clGetEventProfilingInfo(event, CL_PROFILING_COMMAND_START, sizeof start, &start, nullptr),
        "clGetEventProfilingInfo");
  check(clGetEventProfilingInfo(event, CL_PROFILING_COMMAND_END, sizeof end, &end, nullptr),
        "clGetEventProfilingInfo");
  return end > start ? end - start : 0;
}

}  // namespace pxflow::cl
