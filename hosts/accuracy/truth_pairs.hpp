// Frame pairs with known motion for `pxflow accuracy`: real opencv-doc images moved by a seeded
// random affine motion (sub-pixel translation, small rotation or zoom) with the camera's ills
// (noise, blur, brightness change), at 64x64 binned like the PX4FLOW camera and at 320x240.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "frame.hpp"
#include "opencv_api.hpp"

namespace pxflow::accuracy {

// A displacement or a position in pixels (x right, y down).
struct Point2d {
  double x = 0, y = 0;
  friend bool operator==(const Point2d&, const Point2d&) = default;
};

// How prev maps to next: a point p of prev is at motion * (p, 1) in next (frame pixel units,
// pixel centres at integer coordinates, row-major 2x3). Content moving right/down is positive,
// as in SPEC §5.
struct TruthPair {
  std::string name;  // kind, source image and seed, e.g. "rotate+translate/baboon.jpg/seed=7"
  std::string kind;
  Frame prev, next;  // same size
  opencv::Affine motion{};

  // The true displacement of the point (x, y).
  Point2d displacement_at(double x, double y) const;
};

// The two geometries of the table.
enum class Geometry {
  kCamera64,  // full image moved, binned 4x4 (2x2 for small images), 64x64 from the middle
  kWindow320  // full image moved, a 320x240 window from the middle, not binned
};

struct SourceImage {
  std::string name;  // file name within the data directory
  Frame gray;
};

// The opencv-doc images the pairs are made from; throws InputError naming a missing file.
std::vector<SourceImage> load_source_images(const std::string& data_dir);

// `count` pairs of one geometry, seeds first_seed.., kinds and images taken in turn.
std::vector<TruthPair> make_truth_pairs(const std::vector<SourceImage>& images, Geometry g,
                                        int count, std::uint64_t first_seed);

// Consecutive frames of a video, gray.
struct VideoPair {
  std::string name;  // e.g. "vtest.avi#40"
  Frame prev, next;
};
// `count` pairs of consecutive frames spread over the video: frames (k*step, k*step+1) for
// k = 0, 1, ..., step = frame count / count (at least 2).
std::vector<VideoPair> video_pairs(const std::string& path, int count);

}  // namespace pxflow::accuracy
