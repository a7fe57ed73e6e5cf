#include "window_guard.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "errors.hpp"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/asan_interface.h>
#define PXFLOW_ASAN_GUARDS 1
#else
#define PXFLOW_ASAN_GUARDS 0
#endif

namespace pxflow::cpu {
namespace {

constexpr bool kAsanGuards = PXFLOW_ASAN_GUARDS;
constexpr std::uint8_t kGuardByte = 0xA5;

void poison(std::uint8_t* p, std::size_t n, bool on) {
#if PXFLOW_ASAN_GUARDS
  if (on)
    ASAN_POISON_MEMORY_REGION(p, n);
  else
    ASAN_UNPOISON_MEMORY_REGION(p, n);
#else
  (void)p, (void)n, (void)on;
#endif
}

// Rows start 16-byte aligned in the buffer, with at least 8 guard bytes past row_bytes.
int stride_for(int side, int row_bytes) {
  WindowGuard::require_row_bytes(side, row_bytes);
  return (row_bytes + 8 + 15) / 16 * 16;
}

}  // namespace

void WindowGuard::require_row_bytes(int side, int row_bytes) {
  if (row_bytes < side)  // cpu_kernel.hpp: a kernel declares at least the window's 2S+10 bytes
    throw BackendError("cpu kernel: row_bytes = " + std::to_string(row_bytes) +
                       " for a window of " + std::to_string(side) +
                       " columns: it reads the frame past the bytes it declares (internal)");
}

WindowGuard::WindowGuard(int side, int row_bytes)
    : side_(side),
      row_bytes_(row_bytes),
      stride_(stride_for(side, row_bytes)),
      bytes_(2 * kGuard + static_cast<std::size_t>(side) * stride_, kGuardByte),
      tail_(static_cast<std::size_t>(stride_ - side), kGuardByte) {
  std::fill_n(tail_.begin(), row_bytes_ - side_, 0);
  for (int r = 0; r < side_; ++r) {
    std::memset(row(r), 0, static_cast<std::size_t>(row_bytes_));
    poison(row(r) + row_bytes_, static_cast<std::size_t>(stride_ - row_bytes_), true);
  }
  poison(bytes_.data(), kGuard, true);
  poison(row(side_), kGuard, true);
}

WindowGuard::~WindowGuard() { poison(bytes_.data(), bytes_.size(), false); }

// The zeros past each row's pixels and, where ASan does not watch them, the guard bytes: one
// memcmp a row against the bytes each row must hold past its pixels.
void WindowGuard::check(int y0) {
  const auto tail = static_cast<std::size_t>((kAsanGuards ? row_bytes_ : stride_) - side_);
  for (int r = 0; r < side_; ++r) {
    if (std::memcmp(row(r) + side_, tail_.data(), tail) == 0) continue;
    int c = side_;
    while (row(r)[c] == tail_[static_cast<std::size_t>(c - side_)]) ++c;
    changed(y0, "byte " + std::to_string(c) + " of row " + std::to_string(r));
  }
  if (kAsanGuards) return;
  for (int i = 0; i < kGuard; ++i) {
    if (bytes_[static_cast<std::size_t>(i)] != kGuardByte)
      changed(y0, "the guard before the first row");
    if (row(side_)[i] != kGuardByte) changed(y0, "the guard after the last row");
  }
}

void WindowGuard::changed(int y0, const std::string& where) const {
  throw BackendError("cpu window copy: " + where +
                     " changed (the copy of the window at frame row " + std::to_string(y0) +
                     " overran its " + std::to_string(side_) + "-pixel rows; internal)");
}

}  // namespace pxflow::cpu
