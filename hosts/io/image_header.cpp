#include "image_header.hpp"

#include <cctype>
#include <cstdint>
#include <vector>

namespace pxflow {
namespace {

using Bytes = std::vector<std::uint8_t>;

std::uint32_t be32(const Bytes& b, std::size_t at) {
  return std::uint32_t{b[at]} << 24 | std::uint32_t{b[at + 1]} << 16 |
         std::uint32_t{b[at + 2]} << 8 | b[at + 3];
}
std::uint32_t be16(const Bytes& b, std::size_t at) { return std::uint32_t{b[at]} << 8 | b[at + 1]; }
std::int64_t le32s(const Bytes& b, std::size_t at) {
  return static_cast<std::int32_t>(std::uint32_t{b[at]} | std::uint32_t{b[at + 1]} << 8 |
                                   std::uint32_t{b[at + 2]} << 16 | std::uint32_t{b[at + 3]} << 24);
}

FrameSize clamp_size(std::int64_t w, std::int64_t h) {
  // Report absurd values as the largest int so the caller's limit check catches them.
  auto c = [](std::int64_t v) {
    return static_cast<int>(v < 0 ? -v : (v > INT32_MAX ? INT32_MAX : v));
  };
  return {c(w), c(h)};
}

std::optional<FrameSize> pnm_size(const Bytes& b) {
  // "P5 <ws> W <ws> H ..." with '#' comments allowed between fields.
  std::size_t at = 2;
  std::int64_t v[2] = {0, 0};
  for (auto& out : v) {
    while (at < b.size() && (std::isspace(b[at]) || b[at] == '#')) {
      if (b[at] == '#')
        while (at < b.size() && b[at] != '\n') ++at;
      else
        ++at;
    }
    if (at >= b.size() || !std::isdigit(b[at])) return std::nullopt;
    while (at < b.size() && std::isdigit(b[at]) && out < (std::int64_t{1} << 40))
      out = out * 10 + (b[at++] - '0');
  }
  return clamp_size(v[0], v[1]);
}

std::optional<FrameSize> jpeg_size(const Bytes& b) {
  // Walk the marker segments up to the first start-of-frame (SOF0..SOF15 except DHT/JPG/DAC).
  for (std::size_t at = 2; at + 4 <= b.size();) {
    if (b[at] != 0xFF) return std::nullopt;
    const unsigned marker = b[at + 1];
    const std::uint32_t len = be16(b, at + 2);
    if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC) {
      if (at + 9 > b.size()) return std::nullopt;
      return clamp_size(be16(b, at + 7), be16(b, at + 5));
    }
    if (len < 2) return std::nullopt;
    at += 2 + len;
  }
  return std::nullopt;
}

}  // namespace

std::optional<FrameSize> declared_image_size(const Bytes& b) {
  if (b.size() >= 24 && b[0] == 0x89 && b[1] == 'P' && b[2] == 'N' && b[3] == 'G')
    return clamp_size(be32(b, 16), be32(b, 20));  // IHDR follows the 8-byte signature
  if (b.size() >= 26 && b[0] == 'B' && b[1] == 'M')
    return clamp_size(le32s(b, 18), le32s(b, 22));  // BITMAPINFOHEADER; height < 0 = top-down
  if (b.size() >= 3 && b[0] == 'P' && b[1] >= '1' && b[1] <= '6') return pnm_size(b);
  if (b.size() >= 4 && b[0] == 0xFF && b[1] == 0xD8) return jpeg_size(b);
  return std::nullopt;
}

}  // namespace pxflow
