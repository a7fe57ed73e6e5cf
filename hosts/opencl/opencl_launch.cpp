// The commands of one chunk: kernel arguments, frames in, the launch, records out, and their
// profiled times. The queue is in order, so each command starts after the previous one ends.
#include <cstring>

#include "errors.hpp"
#include "grid.hpp"
#include "opencl_backend.hpp"

namespace pxflow {
namespace {

// (first coordinate, step, count, unused) of one grid axis (SPEC sec. 2), as the kernel reads it.
cl_int4 grid_vector(int side, const Params& p) {
  const GridAxis axis = grid_axis_triple(side, p);
  cl_int4 v{};
  v.s[0] = axis.first;
  v.s[1] = axis.step;
  v.s[2] = axis.count;
  return v;
}

template <class T>
void set_arg(cl_kernel kernel, cl_uint index, const T& value) {
  cl::check(clSetKernelArg(kernel, index, sizeof(T), &value),
            "clSetKernelArg " + std::to_string(index));
}

}  // namespace

void OpenclBackend::set_arguments(const Params& p, std::size_t total_pois) {
  cl_kernel k = kernel_.get();
  set_arg(k, 0, frames_.get());
  set_arg(k, 1, records_.records());
  set_arg(k, 2, cl_int{p.width});
  set_arg(k, 3, cl_int{p.height});
  set_arg(k, 4, cl_int{p.search_radius});
  set_arg(k, 5, static_cast<cl_uint>(p.feature_threshold));
  set_arg(k, 6, static_cast<cl_uint>(p.sad_threshold));
  set_arg(k, 7, grid_vector(p.width, p));
  set_arg(k, 8, grid_vector(p.height, p));
  if (tuning_.layout == OpenclLayout::kGroupPerPoi) {
    const std::size_t side = 2 * static_cast<std::size_t>(p.search_radius) + 10;
    cl::check(clSetKernelArg(k, 9, side * side, nullptr), "clSetKernelArg 9 (local window)");
    cl::check(clSetKernelArg(k, 10, group_size_ * sizeof(cl_uint), nullptr),
              "clSetKernelArg 10 (local keys)");
  } else {
    set_arg(k, 9, static_cast<cl_uint>(total_pois));
  }
}

cl::Owned<cl_event> OpenclBackend::upload(std::span<const FramePair> pairs, const Params& p) {
  const std::size_t w = static_cast<std::size_t>(p.width), plane = w * p.height;
  cl_int err = CL_SUCCESS;
  // Mapping lets a CPU driver (PoCL) hand out the buffer itself: one copy, straight from the
  // caller's frames (any stride) into the packed layout the kernel reads.
  auto* dst = static_cast<std::uint8_t*>(
      clEnqueueMapBuffer(queue_.get(), frames_.get(), CL_TRUE, CL_MAP_WRITE_INVALIDATE_REGION, 0,
                         pairs.size() * 2 * plane, 0, nullptr, nullptr, &err));
  cl::check(err, "clEnqueueMapBuffer (frames)");
  for (const FramePair& pair : pairs) {
    for (const FrameView* f : {&pair.prev, &pair.next}) {
      for (int y = 0; y < p.height; ++y) std::memcpy(dst + y * w, f->row(y), w);
      dst += plane;
    }
  }
  cl_event event = nullptr;
  cl::check(clEnqueueUnmapMemObject(queue_.get(), frames_.get(), dst - pairs.size() * 2 * plane, 0,
                                    nullptr, &event),
            "clEnqueueUnmapMemObject (frames)");
  return cl::Owned<cl_event>{event};
}

cl::Owned<cl_event> OpenclBackend::launch(std::size_t total_pois) {
  const bool per_group = tuning_.layout == OpenclLayout::kGroupPerPoi;
  const std::size_t local = group_size_;
  const std::size_t global =
      per_group ? total_pois * local : (total_pois + local - 1) / local * local;
  cl_event event = nullptr;
  cl::check(clEnqueueNDRangeKernel(queue_.get(), kernel_.get(), 1, nullptr, &global, &local, 0,
                                   nullptr, &event),
            "launching the kernel on '" + device_name() + "'");
  return cl::Owned<cl_event>{event};
}

void OpenclBackend::await_kernel(cl_event kernel, const DeviceWork& work) {
  const auto start = std::chrono::steady_clock::now();
  cl::check(clFlush(queue_.get()), "clFlush on '" + device_name() + "'");
  const cl_int status = cl::wait_for_event(kernel, wait_allowance(work));
  if (status < 0) cl::check(status, "the kernel on '" + device_name() + "'");
  if (status == CL_COMPLETE) return;
  const std::chrono::duration<double> waited = std::chrono::steady_clock::now() - start;
  const std::string line =
      wait_failure_line("opencl on '" + device_name() + "'", waited.count(), work);
  abandon(line);
  throw BackendError(line);
}

void OpenclBackend::abandon(const std::string& line) {
  abandoned_ = line;
  note_abandoned_device();
  // Deliberately leaked (see the header): the driver may still run the kernel on them.
  keep_abandoned_handle(queue_.release());
  keep_abandoned_handle(kernel_.release());
  keep_abandoned_handle(frames_.release());
  records_.leak();
}

// Runs only once the kernel completed (await_kernel), so this blocking read never waits on a
// kernel, and nothing is left to write into `out` once run() returned or threw.
cl::Owned<cl_event> OpenclBackend::download(std::span<PoiRecord> out) {
  cl_event event = nullptr;
  cl::check(clEnqueueReadBuffer(queue_.get(), records_.records(), CL_TRUE, 0, out.size_bytes(),
                                out.data(), 0, nullptr, &event),
            "reading the records back from '" + device_name() + "'");
  return cl::Owned<cl_event>{event};
}

void OpenclBackend::account(cl_event upload, cl_event kernel, cl_event download) {
  // A kernel that failed on the device (lost device, out of resources) reports it here, even
  // when the read after it claims success.
  cl_int status = CL_COMPLETE;
  cl::check(
      clGetEventInfo(kernel, CL_EVENT_COMMAND_EXECUTION_STATUS, sizeof status, &status, nullptr),
      "clGetEventInfo");
  if (status < 0) cl::check(status, "the kernel on '" + device_name() + "'");
  timing_.kernel_seconds += 1e-9 * static_cast<double>(cl::event_nanoseconds(kernel));
  timing_.transfer_seconds +=
      1e-9 * static_cast<double>(cl::event_nanoseconds(upload) + cl::event_nanoseconds(download));
  ++timing_.launches;
}

}  // namespace pxflow
