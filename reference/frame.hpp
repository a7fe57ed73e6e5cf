// 8-bit grayscale frames (SPEC §2): a non-owning view, an owning frame, and a pair of views.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pxflow {

struct FrameView {
  int width = 0;
  int height = 0;
  std::ptrdiff_t stride = 0;  // bytes between rows, >= width
  const std::uint8_t* data = nullptr;

  std::uint8_t at(int x, int y) const { return data[y * stride + x]; }
  const std::uint8_t* row(int y) const { return data + y * stride; }
};

// A frame that owns its pixels, rows packed (stride = width).
struct Frame {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;

  FrameView view() const { return {width, height, width, pixels.data()}; }
};

// prev is image1 (where the blocks come from), next is image2 (where they are searched).
struct FramePair {
  FrameView prev;
  FrameView next;
};

}  // namespace pxflow
