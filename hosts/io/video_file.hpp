// A video read frame by frame in gray, through the OpenCV module (cv::VideoCapture): the check
// corpus's and accuracy's real sequences and `pxflow flow` on a video file.
#pragma once
#include <string>

#include "frame.hpp"
#include "opencv_api.hpp"

namespace pxflow {

class VideoFile {
 public:
  // Throws InputError naming the file when it does not exist or cannot be opened as a video.
  explicit VideoFile(const std::string& path);
  ~VideoFile();
  VideoFile(const VideoFile&) = delete;
  VideoFile& operator=(const VideoFile&) = delete;

  // The next frame in gray; false at the end of the video.
  bool read(Frame& out);
  // Skips the next frame without converting it; false at the end.
  bool skip();

 private:
  const opencv::Api& api_;
  opencv::VideoReader* video_ = nullptr;
};

}  // namespace pxflow
