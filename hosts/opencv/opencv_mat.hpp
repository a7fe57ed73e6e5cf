// Inside the module: pxflow's frames as OpenCV matrices and back, and the functions of the table
// (opencv_api.hpp), one file per kind of work.
#pragma once
#include <opencv2/core.hpp>

#include "opencv_api.hpp"

namespace pxflow::opencv {

// A header over the view's pixels, no copy (OpenCV only reads it).
inline cv::Mat mat_of(const FrameView& v) {
  return cv::Mat(v.height, v.width, CV_8UC1, const_cast<std::uint8_t*>(v.data),
                 static_cast<std::size_t>(v.stride));
}

inline Frame frame_of(const cv::Mat& gray) {
  Frame f{gray.cols, gray.rows, std::vector<std::uint8_t>(gray.total())};
  for (int y = 0; y < gray.rows; ++y)
    std::copy_n(gray.ptr<std::uint8_t>(y), gray.cols,
                f.pixels.data() + static_cast<std::size_t>(y) * gray.cols);
  return f;
}

// "" when `img` is an 8-bit image of 1, 3 or 4 channels (converted into `gray`), else why not.
std::string to_gray(const cv::Mat& img, cv::Mat& gray);

// image_io.cpp
void decode_gray(const std::vector<std::uint8_t>& bytes, Frame& out, std::string& error);
VideoReader* open_video(const std::string& path, std::string& error);
bool read_video_frame(VideoReader* video, Frame* out);
void close_video(VideoReader* video);

// flow_picture.cpp
void draw_flow_png(const FlowPicture& picture, std::vector<std::uint8_t>& png, std::string& error);

// image_ops.cpp
Frame warp_affine(const Frame& src, const Affine& m);
void gaussian_blur(Frame& f, double sigma);
void gain_offset(Frame& f, double gain, double offset);
void add_noise(Frame& f, double sigma, std::uint64_t seed);
void lucas_kanade(const FrameView& prev, const FrameView& next, const std::vector<Point2f>& points,
                  std::vector<Point2f>& moved, std::vector<unsigned char>& found);
DisFlow* create_dis();
std::array<double, 2> dis_mean_flow(DisFlow* dis, const FrameView& prev, const FrameView& next);
void destroy_dis(DisFlow* dis);

}  // namespace pxflow::opencv
