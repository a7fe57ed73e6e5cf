#include "frame_io.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "errors.hpp"
#include "image_header.hpp"
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

// Existence, type and emptiness, with the message a user needs.
std::uintmax_t checked_file_size(const std::string& path) {
  require_existing(path);
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (fs::is_directory(st)) throw InputError(path + ": is a directory, not an image file");
  if (!fs::is_regular_file(st)) throw InputError(path + ": not a regular file");
  const auto size = fs::file_size(path, ec);
  if (ec) throw InputError(path + ": cannot read (" + ec.message() + ")");
  if (size == 0) throw InputError(path + ": file is empty");
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw InputError(path + ": cannot open for reading (permissions?)");
  return size;
}

Frame load_raw(const std::string& path, FrameSize size, std::uintmax_t bytes) {
  const auto expected = static_cast<std::uintmax_t>(size.width) * size.height;
  if (bytes != expected)
    throw InputError(path + ": raw file holds " + std::to_string(bytes) + " bytes, but --size " +
                     std::to_string(size.width) + "x" + std::to_string(size.height) + " needs " +
                     std::to_string(expected));
  Frame f{size.width, size.height, std::vector<std::uint8_t>(expected)};
  std::ifstream in(path, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(f.pixels.data()), static_cast<std::streamsize>(expected)))
    throw InputError(path + ": read failed");
  return f;
}

Frame load_image(const std::string& path) {
  if (auto declared = declared_image_size(path))
    check_size_limits(path, declared->width, declared->height);
  Frame f;
  std::string error;
  opencv_api().decode_gray(path, f, error);
  if (!error.empty()) throw InputError(path + ": " + error);
  check_size_limits(path, f.width, f.height);
  return f;
}

}  // namespace

void require_existing(const std::string& path) {
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (!ec && fs::exists(st)) return;
  if (ec == std::errc::too_many_symbolic_link_levels)
    throw InputError(path + ": a loop of symbolic links");
  if (ec == std::errc::permission_denied)
    throw InputError(path + ": cannot be reached (a folder on the way may not be searched)");
  if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory)
    throw InputError(path + ": cannot be opened (" + ec.message() + ")");
  throw InputError(path + ": no such file");
}

FrameSize parse_frame_size(std::string_view text) {
  const auto x = text.find('x');
  if (x == std::string_view::npos)
    throw InputError("--size: '" + std::string(text) + "' is not WIDTHxHEIGHT (e.g. 64x64)");
  const int w = parse_int(text.substr(0, x), "--size width", 1, kMaxFrameSide);
  const int h = parse_int(text.substr(x + 1), "--size height", 1, kMaxFrameSide);
  check_size_limits("--size", w, h);
  return {w, h};
}

bool is_raw_path(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".raw";
}

Frame load_frame(const std::string& path, std::optional<FrameSize> raw_size) {
  const auto bytes = checked_file_size(path);
  if (raw_size) return load_raw(path, *raw_size, bytes);  // --size: raw, whatever the name
  if (is_raw_path(path)) throw InputError(path + ": a .raw file needs --size WIDTHxHEIGHT");
  return load_image(path);
}

}  // namespace pxflow
