// A non-owning view of one 8-bit grayscale frame, and a pair of them (SPEC §2).
#pragma once
#include <cstddef>
#include <cstdint>

namespace pxflow {

struct FrameView {
  int width = 0;
  int height = 0;
  std::ptrdiff_t stride = 0;  // bytes between rows, >= width
  const std::uint8_t* data = nullptr;

  std::uint8_t at(int x, int y) const { return data[y * stride + x]; }
  const std::uint8_t* row(int y) const { return data + y * stride; }
};

// prev is image1 (where the blocks come from), next is image2 (where they are searched).
struct FramePair {
  FrameView prev;
  FrameView next;
};

}  // namespace pxflow
