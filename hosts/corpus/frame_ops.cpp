#include "frame_ops.hpp"

#include <stdexcept>
#include <string>

#include "errors.hpp"
#include "params.hpp"

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

void parse_crop(std::string_view text, FrameShaping& s) {
  const std::string bad = "--crop: '" + std::string(text) +
                          "' is not WxH+X+Y (e.g. 64x64+100+40: a 64x64 window at x=100, y=40)";
  const auto x = text.find('x');
  const auto plus1 = text.find('+');
  const auto plus2 = plus1 == std::string_view::npos ? plus1 : text.find('+', plus1 + 1);
  if (x == std::string_view::npos || plus2 == std::string_view::npos || x > plus1)
    throw InputError(bad);
  try {
    s.crop_w = parse_int(text.substr(0, x), "--crop width", 1, kMaxFrameSide);
    s.crop_h = parse_int(text.substr(x + 1, plus1 - x - 1), "--crop height", 1, kMaxFrameSide);
    s.crop_x = parse_int(text.substr(plus1 + 1, plus2 - plus1 - 1), "--crop x", 0, kMaxFrameSide);
    s.crop_y = parse_int(text.substr(plus2 + 1), "--crop y", 0, kMaxFrameSide);
  } catch (const InputError&) {
    throw InputError(bad);
  }
  s.cropped = true;
}

Frame shape_frame(const Frame& f, const FrameShaping& s) {
  Frame out = f;
  if (s.cropped) {
    if (s.crop_x + s.crop_w > f.width || s.crop_y + s.crop_h > f.height)
      throw InputError("--crop " + std::to_string(s.crop_w) + "x" + std::to_string(s.crop_h) + "+" +
                       std::to_string(s.crop_x) + "+" + std::to_string(s.crop_y) +
                       ": the window does not lie inside the " + std::to_string(f.width) + "x" +
                       std::to_string(f.height) + " frame");
    out = crop(f, s.crop_x, s.crop_y, s.crop_w, s.crop_h);
  }
  if (s.bin > 1) {
    if (out.width / s.bin < 1 || out.height / s.bin < 1)
      throw InputError("--bin " + std::to_string(s.bin) + ": larger than the " +
                       std::to_string(out.width) + "x" + std::to_string(out.height) + " frame");
    out = bin(out, s.bin);
  }
  return out;
}

}  // namespace pxflow
