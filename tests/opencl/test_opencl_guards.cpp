// The guard zones around the OpenCL record buffer (hosts/opencl/cl_guarded_buffer.hpp): a real
// kernel on the device writes into the records' sub-buffer, and bytes it writes past them land in
// the guard, which the check reads back as "wrote past its output".
#include <catch2/catch.hpp>

#include "cl_guarded_buffer.hpp"
#include "cl_program.hpp"
#include "errors.hpp"
#include "opencl_test_support.hpp"
#include "record.hpp"

using namespace pxflow;
using Catch::Matchers::Contains;

TEST_CASE("opencl: a kernel writing past the records hits the guard after them", "[opencl]") {
  test::require_opencl_device();
  const std::vector<cl::DeviceEntry> devices = cl::list_devices();
  const cl::DeviceEntry& device = cl::choose_device(devices, "");
  const cl::Owned<cl_context> context = cl::create_context(device);
  const cl::Owned<cl_program> program = cl::build_program(
      context.get(), device, "kernel void fill(global uchar* out) { out[get_global_id(0)] = 1; }");
  cl_int err = CL_SUCCESS;
  const cl::Owned<cl_command_queue> queue{
      clCreateCommandQueue(context.get(), device.device, 0, &err)};
  cl::check(err, "clCreateCommandQueue");
  const cl::Owned<cl_kernel> kernel{clCreateKernel(program.get(), "fill", &err)};
  cl::check(err, "clCreateKernel");

  constexpr std::size_t kRecords = 64, kBytes = kRecords * sizeof(PoiRecord);
  cl::GuardedBuffer records;
  records.reserve(context.get(), device.device, kBytes);
  const cl_mem inner = records.records();
  cl::check(clSetKernelArg(kernel.get(), 0, sizeof inner, &inner), "clSetKernelArg");
  // Writes `items` bytes from the records' start, then checks the guards.
  auto run = [&](std::size_t items) {
    records.arm(queue.get(), kBytes);
    cl::check(clEnqueueNDRangeKernel(queue.get(), kernel.get(), 1, nullptr, &items, nullptr, 0,
                                     nullptr, nullptr),
              "launch");
    cl::check(clFinish(queue.get()), "clFinish");
    records.check(queue.get(), kBytes, kRecords, "opencl");
  };
  CHECK_NOTHROW(run(kBytes));
  CHECK_THROWS_WITH(run(kBytes + 5), "opencl: wrote past its output (5 bytes after record 63)");
  CHECK_NOTHROW(run(kBytes));  // armed again before each launch
}
