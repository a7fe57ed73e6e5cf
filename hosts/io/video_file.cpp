#include "video_file.hpp"

#include <filesystem>

#include "errors.hpp"
#include "input_file.hpp"
#include "opencv_module.hpp"

namespace pxflow {

namespace {

const opencv::Api& existing_video_api(const std::string& path) {
  require_readable_input(path, path);
  return opencv_api();
}

}  // namespace

VideoFile::VideoFile(const std::string& path) : api_(existing_video_api(path)) {
  std::string error;
  video_ = api_.open_video(path, error);
  if (!video_) throw InputError(path + ": " + error);
}

VideoFile::~VideoFile() { api_.close_video(video_); }

bool VideoFile::read(Frame& out) { return api_.read_video_frame(video_, &out); }

bool VideoFile::skip() { return api_.read_video_frame(video_, nullptr); }

}  // namespace pxflow
