#include "frame_io.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "errors.hpp"
#include "image_header.hpp"
#include "input_file.hpp"
#include "opencv_module.hpp"
#include "params.hpp"

namespace pxflow {
namespace fs = std::filesystem;
namespace {

// Names the one limit a size breaks: a side, or the pixel count (a size whose sides are both in
// range may still have too many pixels).
void check_size_limits(const std::string& what, std::int64_t w, std::int64_t h) {
  const std::string size = std::to_string(w) + "x" + std::to_string(h);
  if (w < 1 || h < 1 || w > kMaxFrameSide || h > kMaxFrameSide)
    throw InputError(what + ": size " + size + ": each side must be 1.." +
                     std::to_string(kMaxFrameSide));
  if (w * h > kMaxFramePixels)
    throw InputError(what + ": size " + size + " is " + std::to_string(w * h) +
                     " pixels, more than the supported " + std::to_string(kMaxFramePixels));
}

// An uncompressed 8-bit BGRA image of kMaxFramePixels, with room for its header: any image file
// pxflow can take is smaller (a stream is read no further).
constexpr std::uint64_t kMaxImageBytes =
    4 * static_cast<std::uint64_t>(kMaxFramePixels) + (1 << 20);

std::string size_text(FrameSize size) {
  return std::to_string(size.width) + "x" + std::to_string(size.height);
}

Frame load_raw(const std::string& path, FrameSize size) {
  const auto expected = static_cast<std::uint64_t>(size.width) * size.height;
  const std::string needs = "but --size " + size_text(size) + " needs " + std::to_string(expected);
  std::vector<std::uint8_t> bytes = read_input(path, path, expected, needs);
  if (bytes.size() != expected)
    throw InputError(path + ": holds " + std::to_string(bytes.size()) + " bytes, " + needs);
  return Frame{size.width, size.height, std::move(bytes)};
}

Frame load_image(const std::string& path) {
  const std::vector<std::uint8_t> bytes = read_input(
      path, path, kMaxImageBytes,
      "more than any 8-bit image of at most " + std::to_string(kMaxFramePixels) + " pixels needs");
  if (auto declared = declared_image_size(bytes))
    check_size_limits(path, declared->width, declared->height);
  Frame f;
  std::string error;
  opencv_api().decode_gray(bytes, f, error);
  if (!error.empty()) throw InputError(path + ": " + error);
  check_size_limits(path, f.width, f.height);
  return f;
}

bool is_raw_path(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".raw";
}

}  // namespace

FrameSize parse_frame_size(std::string_view text) {
  const auto x = text.find('x');
  if (x == std::string_view::npos)
    throw InputError("--size: '" + std::string(text) + "' is not WIDTHxHEIGHT (e.g. 64x64)");
  const int w = parse_int(text.substr(0, x), "--size width", 1, kMaxFrameSide);
  const int h = parse_int(text.substr(x + 1), "--size height", 1, kMaxFrameSide);
  check_size_limits("--size", w, h);
  return {w, h};
}

Frame load_frame(const std::string& path, std::optional<FrameSize> raw_size) {
  if (raw_size) return load_raw(path, *raw_size);  // --size: raw, whatever the name
  require_readable_input(path, path);
  if (is_raw_path(path)) throw InputError(path + ": a .raw file needs --size WIDTHxHEIGHT");
  return load_image(path);
}

}  // namespace pxflow
