// The record buffer with guard zones (hosts/core/guard_zone.hpp): one buffer holding a guard, the
// records the kernel gets as a sub-buffer, and a guard after them. Before each launch both guards
// (and the capacity the launch does not use) are filled with the sentinel; after it they are read
// back, and a changed byte is BackendError "wrote past its output (N bytes after record K)".
#pragma once
#include <cstddef>
#include <string>

#include "cl_util.hpp"

namespace pxflow::cl {

class GuardedBuffer {
 public:
  // Room for `record_bytes` of records (grows, never shrinks) on `device`'s `context`.
  void reserve(cl_context context, cl_device_id device, std::size_t record_bytes);
  cl_mem records() const { return records_.get(); }  // what the kernel writes: the sub-buffer
  std::size_t capacity() const { return capacity_; }
  // Fills the guards and the records' capacity past `used_bytes` with the sentinel.
  void arm(cl_command_queue queue, std::size_t used_bytes);
  // Reads the guards back (blocking: call once the kernel is done); throws BackendError
  // "<who>: wrote past its output (...)" or "... before its output (...)".
  void check(cl_command_queue queue, std::size_t used_bytes, std::size_t records,
             const std::string& who);
  // Gives the buffers up without releasing them (the device abandoned: the kernel may still run).
  void leak();
  // The whole buffer, guards included: tests plant a write there.
  cl_mem whole() const { return whole_.get(); }
  std::size_t front() const { return front_; }

 private:
  Owned<cl_mem> whole_, records_;
  std::size_t front_ = 0, capacity_ = 0;
};

}  // namespace pxflow::cl
