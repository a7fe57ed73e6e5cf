#include "cl_guarded_buffer.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "device_wait.hpp"
#include "guard_zone.hpp"

namespace pxflow::cl {

void GuardedBuffer::reserve(cl_context context, cl_device_id device, std::size_t record_bytes) {
  if (record_bytes <= capacity_ && whole_) return;
  records_.reset();  // release the old buffers before asking for the larger one
  whole_.reset();
  capacity_ = 0;
  // A sub-buffer starts at a multiple of the device's base address alignment (given in bits).
  const auto align =
      std::max<std::size_t>(1, device_value<cl_uint>(device, CL_DEVICE_MEM_BASE_ADDR_ALIGN) / 8);
  front_ = (kGuardBytes + align - 1) / align * align;
  const std::size_t total = front_ + record_bytes + kGuardBytes;
  cl_int err = CL_SUCCESS;
  whole_.reset(clCreateBuffer(context, CL_MEM_WRITE_ONLY, total, nullptr, &err));
  cl::check(err, "clCreateBuffer (" + std::to_string(total) + " bytes of guarded records)");
  const cl_buffer_region region{front_, record_bytes};
  records_.reset(clCreateSubBuffer(whole_.get(), 0, CL_BUFFER_CREATE_TYPE_REGION, &region, &err));
  cl::check(err, "clCreateSubBuffer (the records between their guards)");
  capacity_ = record_bytes;
}

void GuardedBuffer::arm(cl_command_queue queue, std::size_t used_bytes) {
  const cl_uchar pattern = kGuardByte;
  cl::check(clEnqueueFillBuffer(queue, whole_.get(), &pattern, 1, 0, front_, 0, nullptr, nullptr),
            "clEnqueueFillBuffer (the guard before the records)");
  cl::check(clEnqueueFillBuffer(queue, whole_.get(), &pattern, 1, front_ + used_bytes,
                                capacity_ - used_bytes + kGuardBytes, 0, nullptr, nullptr),
            "clEnqueueFillBuffer (the guard after the records)");
}

void GuardedBuffer::check(cl_command_queue queue, std::size_t used_bytes, std::size_t records,
                          const std::string& who) {
  std::vector<std::uint8_t> before(front_), after(capacity_ - used_bytes + kGuardBytes);
  cl::check(clEnqueueReadBuffer(queue, whole_.get(), CL_TRUE, 0, before.size(), before.data(), 0,
                                nullptr, nullptr),
            "reading the guard before the records");
  cl::check(clEnqueueReadBuffer(queue, whole_.get(), CL_TRUE, front_ + used_bytes, after.size(),
                                after.data(), 0, nullptr, nullptr),
            "reading the guard after the records");
  check_guard_before(before, who);
  check_guard_after(after, records, who);
}

void GuardedBuffer::leak() {
  keep_abandoned_handle(records_.release());
  keep_abandoned_handle(whole_.release());
}

}  // namespace pxflow::cl
