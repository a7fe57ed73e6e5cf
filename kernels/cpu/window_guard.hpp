// The buffer into which poi_loop.cpp copies the search window of a POI near the right edge of the
// frame (cpu_kernel.hpp's Window), fenced by guard bytes so that an overrun gets a verdict in
// every build, not only when it changes a record. The checker, not kernel code: the mutation tool
// mutates the copy (poi_loop.cpp), never this file.
//
// Layout: a guard block, then 2S+10 rows of `stride` bytes, then a guard block. Each row holds
// the window's 2S+10 pixels, zeros up to the kernel's row_bytes(S) (which it may read but never
// use) and at least 8 guard bytes up to the stride. check() after every copy: a changed zero or
// guard byte throws BackendError (every build). Under AddressSanitizer the guards are also
// poisoned, so a kernel or a copy that touches one fails there at the access.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pxflow::cpu {

class WindowGuard {
 public:
  WindowGuard(int side, int row_bytes);
  // Throws BackendError unless a kernel's row_bytes covers the window's `side` columns (the
  // constructor's check, for callers that make the buffer only when they need it).
  static void require_row_bytes(int side, int row_bytes);
  WindowGuard(const WindowGuard&) = delete;
  WindowGuard& operator=(const WindowGuard&) = delete;
  ~WindowGuard();

  int side() const { return side_; }
  std::ptrdiff_t stride() const { return stride_; }
  std::uint8_t* row(int r) {
    return bytes_.data() + kGuard + static_cast<std::size_t>(r) * stride_;
  }
  // Throws BackendError naming the first changed byte past a row's pixels (y0: the window's top
  // row in the frame, for the message).
  void check(int y0);

 private:
  [[noreturn]] void changed(int y0, const std::string& where) const;

  static constexpr int kGuard = 64;  // bytes before the first row and after the last
  int side_, row_bytes_, stride_;
  std::vector<std::uint8_t> bytes_;
  std::vector<std::uint8_t> tail_;  // what every row holds past its pixels: zeros, then guards
};

}  // namespace pxflow::cpu
