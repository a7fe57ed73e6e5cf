#include "frame_io.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "errors.hpp"
#include "image_header.hpp"
#include "params.hpp"

namespace pxflow {
namespace fs = std::filesystem;
namespace {

void check_size_limits(const std::string& what, std::int64_t w, std::int64_t h) {
  if (w < 1 || h < 1 || w > kMaxFrameSide || h > kMaxFrameSide || w * h > kMaxFramePixels)
    throw InputError(what + ": size " + std::to_string(w) + "x" + std::to_string(h) +
                     " is outside the supported 1x1.." + std::to_string(kMaxFrameSide) + "x" +
                     std::to_string(kMaxFrameSide) + " (at most " +
                     std::to_string(kMaxFramePixels) + " pixels)");
}

// Existence, type and emptiness, with the message a user needs.
std::uintmax_t checked_file_size(const std::string& path) {
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw InputError(path + ": no such file");
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

// libpng and libjpeg print their own complaints straight to stderr, below OpenCV's logger.
// While a decoder runs, fd 2 points at /dev/null, so a bad file gives our one line only.
class StderrSilenced {
 public:
  StderrSilenced() : saved_(dup(2)) {
    const int null_fd = open("/dev/null", O_WRONLY);
    if (null_fd >= 0) {
      dup2(null_fd, 2);
      close(null_fd);
    }
  }
  ~StderrSilenced() {
    if (saved_ >= 0) {
      dup2(saved_, 2);
      close(saved_);
    }
  }
  StderrSilenced(const StderrSilenced&) = delete;
  StderrSilenced& operator=(const StderrSilenced&) = delete;

 private:
  int saved_;
};

Frame load_image(const std::string& path) {
  if (auto declared = declared_image_size(path))
    check_size_limits(path, declared->width, declared->height);
  cv::Mat img;
  try {
    StderrSilenced quiet;
    img = cv::imread(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception&) {
    img.release();
  }
  if (img.empty())
    throw InputError(path + ": cannot decode as an image (corrupt, truncated or unknown format)");
  if (img.depth() != CV_8U)
    throw InputError(path + ": " + (img.depth() == CV_16U ? "16-bit" : "non-8-bit") +
                     " image; pxflow needs 8-bit frames (convert it, e.g. to 8-bit PNG)");
  check_size_limits(path, img.cols, img.rows);
  cv::Mat gray;
  switch (img.channels()) {
    case 1:
      gray = img;
      break;
    case 3:
      cv::cvtColor(img, gray, cv::COLOR_BGR2GRAY);
      break;  // OpenCV's weights
    case 4:
      cv::cvtColor(img, gray, cv::COLOR_BGRA2GRAY);
      break;
    default:
      throw InputError(path + ": " + std::to_string(img.channels()) +
                       "-channel image; expected gray, BGR or BGRA");
  }
  Frame f{gray.cols, gray.rows, {}};
  f.pixels.resize(static_cast<std::size_t>(gray.cols) * gray.rows);
  for (int y = 0; y < gray.rows; ++y)
    std::copy_n(gray.ptr<std::uint8_t>(y), gray.cols, f.pixels.data() + y * gray.cols);
  return f;
}

}  // namespace

void quiet_opencv() { cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT); }

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
  if (is_raw_path(path)) {
    if (!raw_size) throw InputError(path + ": a .raw file needs --size WIDTHxHEIGHT");
    return load_raw(path, *raw_size, bytes);
  }
  if (raw_size)
    throw InputError(path + ": --size applies to .raw files only (image files carry their size)");
  return load_image(path);
}

}  // namespace pxflow
