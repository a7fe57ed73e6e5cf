#include "opencl_backend.hpp"

#include <algorithm>
#include <cstring>

#include "errors.hpp"
#include "grid.hpp"

namespace pxflow {
namespace {

// Caps that keep one launch modest even where the device would allow more: host staging memory
// stays bounded, and no single launch runs long enough to trip a GPU driver's watchdog.
constexpr std::size_t kDefaultChunkBytes = std::size_t{256} << 20;
constexpr std::size_t kMaxGroupsPerLaunch = std::size_t{1} << 20;
// Measured against 16..256: docs/measurements/opencl-kernel.md.
constexpr std::size_t kDefaultGroupSize = 64;

const char* kernel_name(OpenclLayout layout) {
  return layout == OpenclLayout::kGroupPerPoi ? "flow_group_per_poi" : "flow_item_per_poi";
}

std::size_t floor_pow2(std::size_t n) {
  std::size_t p = 1;
  while (p * 2 <= n) p *= 2;
  return p;
}

}  // namespace

OpenclBackend::OpenclBackend(const BackendOptions& options, const OpenclTuning& tuning)
    : OpenclBackend(tuning,
                    cl::device_program(cl::choose_device(cl::list_devices(), options.device))) {}

OpenclBackend::OpenclBackend(const OpenclTuning& tuning,
                             std::shared_ptr<const cl::DeviceProgram> program)
    : tuning_(tuning), program_(std::move(program)) {
  const cl_device_id device = program_->device.device;
  // Records leave the device as uint words in the layout of a little-endian PoiRecord.
  if (!cl::device_value<cl_bool>(device, CL_DEVICE_ENDIAN_LITTLE))
    throw BackendError("opencl: device '" + device_name() + "' is big-endian (not supported)");

  // PoCL runs a work-group as a loop over its work-items on one core: barriers and local
  // memory only add work there, while a GPU needs the group's parallelism (docs/opencl.md).
  if (tuning_.layout == OpenclLayout::kAuto)
    tuning_.layout = program_->device.cpu ? OpenclLayout::kItemPerPoi : OpenclLayout::kGroupPerPoi;

  cl_int err = CL_SUCCESS;
  queue_.reset(
      clCreateCommandQueue(program_->context.get(), device, CL_QUEUE_PROFILING_ENABLE, &err));
  cl::check(err, "clCreateCommandQueue on '" + device_name() + "'");
  kernel_.reset(clCreateKernel(program_->program.get(), kernel_name(tuning_.layout), &err));
  cl::check(err, std::string("clCreateKernel ") + kernel_name(tuning_.layout));

  read_device_limits();
}

void OpenclBackend::read_device_limits() {
  const cl_device_id device = program_->device.device;
  std::size_t kernel_max = 0;
  cl::check(clGetKernelWorkGroupInfo(kernel_.get(), device, CL_KERNEL_WORK_GROUP_SIZE,
                                     sizeof kernel_max, &kernel_max, nullptr),
            "clGetKernelWorkGroupInfo");
  const std::size_t wanted = tuning_.group_size ? tuning_.group_size : kDefaultGroupSize;
  group_size_ = std::min(wanted, floor_pow2(kernel_max));

  cl_ulong kernel_local = 0;
  cl::check(clGetKernelWorkGroupInfo(kernel_.get(), device, CL_KERNEL_LOCAL_MEM_SIZE,
                                     sizeof kernel_local, &kernel_local, nullptr),
            "clGetKernelWorkGroupInfo");
  const auto local = cl::device_value<cl_ulong>(device, CL_DEVICE_LOCAL_MEM_SIZE);
  limits_.local_bytes = local > kernel_local ? local - kernel_local : 0;
  const auto max_alloc = cl::device_value<cl_ulong>(device, CL_DEVICE_MAX_MEM_ALLOC_SIZE);
  const auto global = cl::device_value<cl_ulong>(device, CL_DEVICE_GLOBAL_MEM_SIZE);
  // Frames and records share global memory; leave room for other users of the device.
  limits_.chunk_bytes = static_cast<std::size_t>(std::min<cl_ulong>(max_alloc, global / 4));
  limits_.chunk_bytes = std::min(
      limits_.chunk_bytes, tuning_.max_chunk_bytes ? tuning_.max_chunk_bytes : kDefaultChunkBytes);
}

Backend::Description OpenclBackend::describe() const {
  const cl::DeviceEntry& d = program_->device;
  return {std::string("kernels/opencl/opencl.cl ") + kernel_name(tuning_.layout) + ", group size " +
              std::to_string(group_size_),
          d.name + " (#" + std::to_string(d.index) + ")",
          d.platform_name + ", " + cl::platform_string(d.platform, CL_PLATFORM_VERSION) +
              ", driver " + cl::device_string(d.device, CL_DRIVER_VERSION)};
}

std::string OpenclBackend::device_kind() const {
  const cl::DeviceEntry& d = program_->device;
  return d.cpu ? "cpu" : d.gpu ? "gpu" : "other";
}

OpenclBackend::~OpenclBackend() {
  // No buffer is released while a command still uses it; an abandoned device's were leaked.
  if (queue_ && abandoned_.empty()) clFinish(queue_.get());
}

std::size_t OpenclBackend::local_window_bytes(const Params& p) const {
  if (tuning_.layout != OpenclLayout::kGroupPerPoi) return 0;
  const std::size_t side = 2 * static_cast<std::size_t>(p.search_radius) + 10;
  return side * side + group_size_ * sizeof(cl_uint);
}

std::size_t OpenclBackend::pairs_per_chunk(const Params& p) const {
  const std::size_t frame_bytes = 2 * static_cast<std::size_t>(p.width) * p.height;
  const std::size_t pois = poi_count(p);
  const std::size_t groups_per_pair =
      tuning_.layout == OpenclLayout::kGroupPerPoi ? pois : (pois + group_size_ - 1) / group_size_;
  return std::min({limits_.chunk_bytes / frame_bytes, limits_.chunk_bytes / (pois * 32),
                   kMaxGroupsPerLaunch / groups_per_pair});
}

std::string OpenclBackend::unsupported(const Params& p) const {
  if (local_window_bytes(p) > limits_.local_bytes)
    return "search_radius " + std::to_string(p.search_radius) + " needs " +
           std::to_string(local_window_bytes(p)) + " bytes of local memory, device '" +
           device_name() + "' has " + std::to_string(limits_.local_bytes);
  if (pairs_per_chunk(p) == 0)
    return "one " + std::to_string(p.width) + "x" + std::to_string(p.height) +
           " frame pair exceeds the device's buffer limit of " +
           std::to_string(limits_.chunk_bytes) + " bytes";
  return {};
}

void OpenclBackend::run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
                        OpCounts&) {
  timing_ = {};
  if (!abandoned_.empty())
    throw BackendError("opencl: device '" + device_name() +
                       "' unusable after an earlier failure: " + abandoned_);
  if (pairs.empty()) return;
  try {
    if (const std::string why = unsupported(p); !why.empty()) throw BackendError("opencl: " + why);
    run_chunks(pairs, p, out);
  } catch (...) {
    // Never hand back a half-written batch: a zero record has x = 0, which no grid POI has.
    std::memset(out.data(), 0, out.size_bytes());
    throw;
  }
}

void OpenclBackend::run_chunks(std::span<const FramePair> pairs, const Params& p,
                               std::span<PoiRecord> out) {
  const std::size_t per_chunk = std::min(pairs.size(), pairs_per_chunk(p));
  const std::size_t pois = poi_count(p);
  reserve_buffers(per_chunk * 2 * static_cast<std::size_t>(p.width) * p.height,
                  per_chunk * pois * sizeof(PoiRecord));
  for (std::size_t first = 0; first < pairs.size(); first += per_chunk) {
    const std::size_t n = std::min(per_chunk, pairs.size() - first);
    set_arguments(p, n * pois);
    const auto in = upload(pairs.subspan(first, n), p);
    records_.arm(queue_.get(), n * pois * sizeof(PoiRecord));
    const auto kernel = launch(n * pois);
    await_kernel(kernel.get(), DeviceWork{n, pois, p.search_radius});
    const auto back = download(out.subspan(first * pois, n * pois));
    records_.check(queue_.get(), n * pois * sizeof(PoiRecord), n * pois, "opencl");
    account(in.get(), kernel.get(), back.get());
  }
}

void OpenclBackend::reserve_buffers(std::size_t frame_bytes, std::size_t record_bytes) {
  cl_int err = CL_SUCCESS;
  if (frame_bytes > frames_capacity_) {
    frames_.reset();  // release the old buffer before asking for the larger one
    frames_capacity_ = 0;
    frames_.reset(clCreateBuffer(program_->context.get(), CL_MEM_READ_ONLY | CL_MEM_ALLOC_HOST_PTR,
                                 frame_bytes, nullptr, &err));
    cl::check(err, "clCreateBuffer (" + std::to_string(frame_bytes) + " bytes of frames)");
    frames_capacity_ = frame_bytes;
  }
  records_.reserve(program_->context.get(), program_->device.device, record_bytes);
}

}  // namespace pxflow
