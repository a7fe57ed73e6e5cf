// The operations pxflow needs from OpenCV, as one table of function pointers. They live in a
// shared module (libpxflow_opencv.so, hosts/opencv/) that the pxflow binary loads only when a
// frame must be decoded, a video read, a picture drawn or a warp made (hosts/io/opencv_module.hpp):
// loading OpenCV's ~250 shared libraries costs ~200 ms, which every other command (--help,
// --version, flow on raw frames, check on generated inputs) no longer pays.
//
// Only pxflow's header-only types cross the boundary (Frame, FrameView, PoiRecord, FrameResult,
// std::string, std::vector): the module and the binary are built together by one compiler and
// share libstdc++. Calls that can fail on a user's input report it in an `error` string (empty:
// success) instead of throwing, so no exception type has to match across the boundary.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "frame.hpp"
#include "record.hpp"

namespace pxflow::opencv {

// Bumped whenever the table below changes; the loader refuses a module of another version.
inline constexpr int kApiVersion = 2;

// The name of the one exported function: `const Api* pxflow_opencv_api()`.
inline constexpr const char* kEntryPoint = "pxflow_opencv_api";

struct VideoReader;  // an open cv::VideoCapture
struct DisFlow;      // a cv::DISOpticalFlow, built once and reused

// A 2x3 affine map (row-major, OpenCV's warpAffine convention: a point p of the source lands at
// M * (p, 1)).
using Affine = std::array<double, 6>;

struct Point2f {
  float x = 0, y = 0;
};

// What the flow picture shows (hosts/io/draw_flow.hpp decides the layout, the module draws).
struct FlowPicture {
  FrameView prev;
  std::span<const PoiRecord> records;
  FrameResult result;
  int scale = 1;                         // screen pixels per frame pixel
  int gain = 1;                          // POI vectors drawn this many times their length
  int flow_gain = 1;                     // the frame-flow arrow likewise
  std::string frames, backend, profile;  // the caption
};

struct Api {
  int version = kApiVersion;

  // Silences OpenCV's own log lines, so that a bad file gives pxflow's one error line only.
  void (*quiet)();
  // OpenCV's worker threads (cv::setNumThreads).
  void (*set_threads)(int threads);

  // The bytes of any 8-bit image cv::imdecode reads (the whole file, so that a pipe decodes like a
  // file), converted to gray the OpenCV way (BGR/BGRA weights). On failure `out` is untouched and
  // the error says why (not naming the path).
  void (*decode_gray)(const std::vector<std::uint8_t>& bytes, Frame& out, std::string& error);
  // PNG bytes of the flow picture; on failure the error says why.
  void (*draw_flow_png)(const FlowPicture& picture, std::vector<std::uint8_t>& png,
                        std::string& error);

  // Video through cv::VideoCapture. open returns null and sets `error` when the file cannot be
  // opened as a video. read gives the next frame in gray (`out` null: skip it without the
  // colour conversion) and returns false at the end.
  VideoReader* (*open_video)(const std::string& path, std::string& error);
  bool (*read_video_frame)(VideoReader* video, Frame* out);
  void (*close_video)(VideoReader* video);

  // Known motion and the camera's ills (the check corpus and the accuracy pairs): a bilinear
  // warp with reflected borders, same size; a Gaussian blur of this sigma; gain and offset
  // (rounded, saturated); Gaussian noise of this sigma from cv::RNG(seed), saturated.
  Frame (*warp_affine)(const Frame& src, const Affine& m);
  void (*gaussian_blur)(Frame& f, double sigma);
  void (*gain_offset)(Frame& f, double gain, double offset);
  void (*add_noise)(Frame& f, double sigma, std::uint64_t seed);

  // pxflow accuracy's competitors: pyramidal Lucas-Kanade (OpenCV's defaults: 21x21 window, 3
  // levels) from `points`, and DIS flow (ultrafast preset) averaged over every pixel.
  void (*lucas_kanade)(const FrameView& prev, const FrameView& next,
                       const std::vector<Point2f>& points, std::vector<Point2f>& moved,
                       std::vector<unsigned char>& found);
  DisFlow* (*create_dis)();
  std::array<double, 2> (*dis_mean_flow)(DisFlow* dis, const FrameView& prev,
                                         const FrameView& next);
  void (*destroy_dis)(DisFlow* dis);
};

}  // namespace pxflow::opencv

// The module's one exported symbol.
extern "C" const pxflow::opencv::Api* pxflow_opencv_api();
