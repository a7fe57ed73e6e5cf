// Frames in through OpenCV: images (cv::imread) and videos (cv::VideoCapture), gray.
#include <fcntl.h>
#include <unistd.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "opencv_mat.hpp"

namespace pxflow::opencv {
namespace {

// libpng and libjpeg print their own complaints straight to stderr, below OpenCV's logger.
// While a decoder runs, fd 2 points at /dev/null, so a bad file gives pxflow's one line only.
class StderrSilenced {
 public:
  StderrSilenced() : saved_(dup(2)) {
    const int null_fd = open("/dev/null", O_WRONLY | O_CLOEXEC);
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

}  // namespace

struct VideoReader {
  cv::VideoCapture capture;
  cv::Mat frame, gray;
};

std::string to_gray(const cv::Mat& img, cv::Mat& gray) {
  if (img.depth() != CV_8U)
    return std::string(img.depth() == CV_16U ? "16-bit" : "non-8-bit") +
           " image; pxflow needs 8-bit frames (convert it, e.g. to 8-bit PNG)";
  switch (img.channels()) {
    case 1:
      gray = img;
      return {};
    case 3:
      cv::cvtColor(img, gray, cv::COLOR_BGR2GRAY);  // OpenCV's weights
      return {};
    case 4:
      cv::cvtColor(img, gray, cv::COLOR_BGRA2GRAY);
      return {};
    default:
      return std::to_string(img.channels()) + "-channel image; expected gray, BGR or BGRA";
  }
}

void decode_gray(const std::vector<std::uint8_t>& bytes, Frame& out, std::string& error) {
  cv::Mat img, gray;
  try {
    StderrSilenced quiet;
    img = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception&) {
    img.release();
  }
  if (img.empty()) {
    error = "cannot decode as an image (corrupt, truncated or unknown format)";
    return;
  }
  error = to_gray(img, gray);
  if (error.empty()) out = frame_of(gray);
}

VideoReader* open_video(const std::string& path, std::string& error) {
  auto video = std::make_unique<VideoReader>();
  try {
    StderrSilenced quiet;
    video->capture.open(path);
  } catch (const cv::Exception&) {
  }
  if (!video->capture.isOpened()) {
    error = "cannot open as a video (no decoder for it, or not a video)";
    return nullptr;
  }
  return video.release();
}

bool read_video_frame(VideoReader* video, Frame* out) {
  try {
    if (!out) return video->capture.grab();
    if (!video->capture.read(video->frame) || video->frame.empty()) return false;
    if (!to_gray(video->frame, video->gray).empty()) return false;
    *out = frame_of(video->gray);
    return true;
  } catch (const cv::Exception&) {
    return false;
  }
}

void close_video(VideoReader* video) { delete video; }

}  // namespace pxflow::opencv
