#include "frame_sequence.hpp"

#include <fcntl.h>
#include <glob.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "counted.hpp"
#include "errors.hpp"
#include "file_inputs.hpp"
#include "input_file.hpp"
#include "video_file.hpp"

namespace pxflow {
namespace {

namespace fs = std::filesystem;

std::string lower_extension(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// The extensions a folder's image frames may have (what cv::imread reads on Debian).
bool is_image_name(const fs::path& p) {
  static const char* const kExtensions[] = {".png", ".jpg", ".jpeg", ".bmp",  ".pgm", ".ppm",
                                            ".pnm", ".tif", ".tiff", ".webp", ".raw"};
  const std::string ext = lower_extension(p);
  return std::any_of(std::begin(kExtensions), std::end(kExtensions),
                     [&](const char* e) { return ext == e; });
}

class FileFrames final : public FrameSequence {
 public:
  FileFrames(std::vector<std::string> paths, std::optional<FrameSize> raw_size)
      : paths_(std::move(paths)), raw_size_(raw_size) {}
  bool next(NamedFrame& out) override {
    if (next_ >= paths_.size()) return false;
    out.name = paths_[next_++];
    out.frame = load_frame(out.name, raw_size_);
    return true;
  }
  std::vector<std::string> files() const override { return paths_; }

 private:
  std::vector<std::string> paths_;
  std::optional<FrameSize> raw_size_;
  std::size_t next_ = 0;
};

class VideoFrames final : public FrameSequence {
 public:
  explicit VideoFrames(const std::string& path)
      : path_(path), name_(fs::path(path).filename().string()), video_(path) {}
  bool next(NamedFrame& out) override {
    if (!video_.read(out.frame)) return false;
    out.name = name_ + "#" + std::to_string(index_++);
    return true;
  }
  std::vector<std::string> files() const override { return {path_}; }

 private:
  std::string path_, name_;
  VideoFile video_;
  int index_ = 0;
};

// W*H bytes per frame, back to back, from a file or standard input (fd 0).
class RawFrames final : public FrameSequence {
 public:
  RawFrames(const std::string& source, FrameSize size) : source_(source), size_(size) {
    if (source == "-") return;
    fd_ = open_or_stop(source, source);
    if (fd_ < 0)
      throw InputError(source + ": cannot open for reading (" + std::strerror(errno) + ")");
  }
  ~RawFrames() override {
    if (fd_ > 0) ::close(fd_);
  }
  bool next(NamedFrame& out) override {
    const std::size_t bytes = static_cast<std::size_t>(size_.width) * size_.height;
    std::vector<std::uint8_t> px(bytes);
    std::size_t got = 0;
    while (got < bytes) {
      const long n = read_or_stop(fd_, px.data() + got, bytes - got, source_);
      if (n < 0) throw InputError(source_ + ": read failed (" + std::strerror(errno) + ")");
      if (n == 0) break;
      got += static_cast<std::size_t>(n);
    }
    if (got == 0) return false;
    if (got < bytes)
      throw InputError(source_ + ": ends in a partial frame (" + std::to_string(got) + " of the " +
                       std::to_string(bytes) + " bytes --size " + std::to_string(size_.width) +
                       "x" + std::to_string(size_.height) + " needs)");
    out.name = source_ + "#" + std::to_string(index_++);
    out.frame = Frame{size_.width, size_.height, std::move(px)};
    return true;
  }
  std::vector<std::string> files() const override {
    return source_ == "-" ? std::vector<std::string>{} : std::vector<std::string>{source_};
  }

 private:
  std::string source_;
  FrameSize size_;
  int fd_ = 0;
  int index_ = 0;
};

std::vector<std::string> folder_frames(const std::string& dir, bool raw) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const fs::path& p = entry.path();
    if (p.filename().string().starts_with('.') || !entry.is_regular_file(ec)) continue;
    if (raw || is_image_name(p)) out.push_back(p.string());
  }
  if (ec) throw InputError(dir + ": cannot list the folder (" + ec.message() + ")");
  std::sort(out.begin(), out.end());
  if (out.size() < 2)
    throw InputError(dir + ": a folder of frames needs at least 2 " +
                     (raw ? std::string("files") : "image files (.png, .jpg, .pgm, ...)") +
                     ", found " + std::to_string(out.size()));
  return out;
}

std::vector<std::string> glob_frames(const std::string& pattern) {
  glob_t g{};
  const int rc = ::glob(pattern.c_str(), 0, nullptr, &g);  // sorted by name
  std::vector<std::string> out;
  if (rc == 0)
    for (std::size_t i = 0; i < g.gl_pathc; ++i) out.push_back(g.gl_pathv[i]);
  ::globfree(&g);
  if (out.size() < 2)
    throw InputError(pattern + ": the pattern matches " + counted(out.size(), "file") +
                     "; a sequence needs at least 2 frames");
  return out;
}

}  // namespace

std::unique_ptr<FrameSequence> open_frame_sequence(const std::string& source,
                                                   std::optional<FrameSize> raw_size) {
  if (source == "-") {
    if (!raw_size)
      throw InputError("-: frames on standard input are raw; give their size with --size WxH");
    return std::make_unique<RawFrames>(source, *raw_size);
  }
  std::error_code ec;
  const auto st = fs::status(source, ec);
  if (fs::is_directory(st)) {
    note_input_folder("SOURCE", source);  // a file written inside would be read as a frame
    return std::make_unique<FileFrames>(folder_frames(source, raw_size.has_value()), raw_size);
  }
  if (!fs::exists(st) && source.find_first_of("*?[") != std::string::npos) {
    std::vector<std::string> files = glob_frames(source);
    for (const std::string& f : files) note_input(f);
    return std::make_unique<FileFrames>(std::move(files), raw_size);
  }
  require_readable_input(source, source);
  if (raw_size) return std::make_unique<RawFrames>(source, *raw_size);
  if (is_image_name(source))
    throw InputError(source +
                     ": one image is not a sequence; give PREV NEXT for one pair, or a video, a "
                     "folder or a glob of frames as SOURCE (see pxflow flow --help)");
  return std::make_unique<VideoFrames>(source);
}

std::vector<std::pair<std::string, std::string>> read_pair_list(const std::string& option,
                                                                const std::string& path) {
  const std::string label = option + " " + path;
  std::istringstream in(read_input_text(label, path));
  // A list through a pipe (--pairs <(...)) has no folder of its own: its paths are the shell's.
  const fs::path dir = is_stream(path) ? fs::path() : fs::path(path).parent_path();
  auto resolve = [&](const std::string& p) {
    return fs::path(p).is_absolute() || dir.empty() ? p : (dir / p).string();
  };
  std::vector<std::pair<std::string, std::string>> pairs;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const auto start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '#') continue;
    std::istringstream fields(line);
    std::string prev, next, extra;
    fields >> std::quoted(prev) >> std::quoted(next);
    if (!fields || (fields >> extra))
      throw InputError(label + ":" + std::to_string(number) +
                       ": expected two paths, PREV NEXT (quote a path with spaces)");
    pairs.push_back({resolve(prev), resolve(next)});
  }
  if (pairs.empty()) throw InputError(label + ": lists no pair");
  return pairs;
}

}  // namespace pxflow
