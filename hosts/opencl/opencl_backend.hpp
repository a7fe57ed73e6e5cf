// The opencl family's backend: a kernel of kernels/opencl/opencl.cl run through the OpenCL C API on
// one device (PoCL's CPU device here, any OpenCL 1.2 driver elsewhere). A batch is packed into
// one frame buffer and run with one launch, split into chunks only where the device's limits
// (max allocation, global memory) demand it. Work decomposition and measurements: docs/opencl.md.
#pragma once
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "backend.hpp"
#include "cl_guarded_buffer.hpp"
#include "cl_program.hpp"
#include "device_wait.hpp"

namespace pxflow {

// Which kernel of opencl.cl runs. Each is a registry row (opencl_rows.cpp: `opencl` = kAuto,
// `opencl-item`, `opencl-group`), so `pxflow check` and `bench` run every layout the backend
// ships (docs/opencl.md).
enum class OpenclLayout {
  kAuto,         // item-per-poi on CPU devices, group-per-poi on GPUs and accelerators
  kGroupPerPoi,  // flow_group_per_poi: a work-group per POI, window in local memory
  kItemPerPoi,   // flow_item_per_poi: a work-item per POI, global memory only
};

struct OpenclTuning {
  OpenclLayout layout = OpenclLayout::kAuto;
  std::size_t group_size = 0;       // work-items per work-group; 0 = chosen for the device
  std::size_t max_chunk_bytes = 0;  // cap on one launch's buffers; 0 = the device's limits
};

// Where the time of the last run() went, from OpenCL event profiling (device clock).
struct OpenclTiming {
  double kernel_seconds = 0;    // all launches of the run, START to END
  double transfer_seconds = 0;  // frames in (unmap) and records out (read)
  int launches = 0;
};

class OpenclBackend final : public Backend {
 public:
  // Throws InputError for a device selector that names no device, BackendError when the
  // driver fails or the kernel does not build (with the build log).
  explicit OpenclBackend(const BackendOptions& options, const OpenclTuning& tuning = {});
  // Runs the kernels of `program` (built for its device) instead of opencl.cl's: the hang tests
  // give one whose flow_item_per_poi never ends (tests/opencl/spin.cl).
  OpenclBackend(const OpenclTuning& tuning, std::shared_ptr<const cl::DeviceProgram> program);
  ~OpenclBackend() override;

  void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
           OpCounts& counts) override;
  std::string unsupported(const Params& p) const override;

  const OpenclTiming& last_timing() const { return timing_; }
  // Kernel time of the last run by OpenCL event profiling (transfers excluded), for the bench.
  std::optional<DeviceTime> last_device_time() const override {
    if (timing_.launches == 0) return std::nullopt;
    return DeviceTime{"opencl-event-profiling", timing_.kernel_seconds * 1e9, std::nullopt};
  }
  const std::string& device_name() const { return program_->device.name; }
  // The kernel layout, the device and the platform's version string (PoCL's names its release).
  Description describe() const override;
  std::string device_kind() const override;  // CL_DEVICE_TYPE: "cpu", "gpu", "other"
  std::size_t group_size() const { return group_size_; }
  OpenclLayout layout() const { return tuning_.layout; }  // never kAuto

 private:
  struct Limits {
    std::size_t chunk_bytes = 0;  // the most one launch's frame or record buffer may hold
    std::size_t local_bytes = 0;  // local memory left for the kernel's dynamic arguments
  };

  void read_device_limits();  // group size, local memory and buffer caps
  std::size_t pairs_per_chunk(const Params& p) const;
  std::size_t local_window_bytes(const Params& p) const;
  void reserve_buffers(std::size_t frame_bytes, std::size_t record_bytes);
  void set_arguments(const Params& p, std::size_t total_pois);
  // The three commands of a chunk, each returning its profiled event.
  cl::Owned<cl_event> upload(std::span<const FramePair> pairs, const Params& p);
  cl::Owned<cl_event> launch(std::size_t total_pois);
  cl::Owned<cl_event> download(std::span<PoiRecord> out);
  // Flushes the queue and waits for the kernel (cl::wait_for_event) as long as `work` allows;
  // when that runs out, abandons the device (abandon()) and throws the wait's line.
  void await_kernel(cl_event kernel, const DeviceWork& work);
  // Gives up a device whose kernel may still run: leaks the queue, kernel and buffers (releasing
  // them, or clFinish, would wait for the kernel forever) and refuses every later run.
  void abandon(const std::string& line);
  void account(cl_event upload, cl_event kernel, cl_event download);
  void run_chunks(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out);

  OpenclTuning tuning_;
  std::shared_ptr<const cl::DeviceProgram> program_;
  cl::Owned<cl_command_queue> queue_;
  cl::Owned<cl_kernel> kernel_;
  cl::Owned<cl_mem> frames_;
  cl::GuardedBuffer records_;  // the records between guard zones, checked after every launch
  std::size_t frames_capacity_ = 0;
  std::size_t group_size_ = 0;
  Limits limits_;
  OpenclTiming timing_;
  std::string abandoned_;  // the line of the wait that gave the device up
};

}  // namespace pxflow
