#include "frame_ops.hpp"

#include <stdexcept>

namespace pxflow {

Frame crop(const Frame& f, int x, int y, int w, int h) {
  if (x < 0 || y < 0 || w < 1 || h < 1 || x + w > f.width || y + h > f.height)
    throw std::out_of_range("crop window outside the frame");
  Frame out{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h)};
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) out.pixels[r * w + c] = f.pixels[(y + r) * f.width + x + c];
  return out;
}

Frame bin(const Frame& f, int factor) {
  if (factor < 1) throw std::invalid_argument("binning factor must be >= 1");
  const int w = f.width / factor, h = f.height / factor, n = factor * factor;
  Frame out{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h)};
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      int sum = 0;
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx)
          sum += f.pixels[(r * factor + dy) * f.width + c * factor + dx];
      out.pixels[r * w + c] = static_cast<std::uint8_t>((sum + n / 2) / n);
    }
  return out;
}

}  // namespace pxflow
