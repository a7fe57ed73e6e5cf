// The three ways to get one frame's motion that `pxflow accuracy` compares: pxflow's frame flow
// through a registry backend, OpenCV's pyramidal Lucas-Kanade on pxflow's POIs averaged the way
// pxflow's estimate averages, and OpenCV's DIS flow (ultrafast preset) averaged over the frame.
// OpenCV's two run in the OpenCV module (hosts/opencv/image_ops.cpp).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "backend.hpp"
#include "opencv_api.hpp"
#include "params.hpp"
#include "record.hpp"
#include "truth_pairs.hpp"

namespace pxflow::accuracy {

struct FlowEstimate {
  Point2d flow;        // pixels per frame, content motion right/down positive
  bool valid = false;  // pxflow: quality > 0; LK: more than MINCOUNT points tracked; DIS: always
};

// pxflow's frame flow (SPEC §5) from one backend's records.
class PxflowEstimator {
 public:
  PxflowEstimator(const std::string& backend_name, const BackendOptions& options, const Params& p);
  FlowEstimate estimate(const Frame& prev, const Frame& next);
  // Where the averages of the other methods are taken: the centres of the POI blocks.
  const std::vector<opencv::Point2f>& poi_centres() const { return centres_; }
  const Params& params() const { return p_; }

 private:
  std::unique_ptr<Backend> backend_;
  Params p_;
  std::vector<opencv::Point2f> centres_;
  std::vector<PoiRecord> records_;
};

// Pyramidal Lucas-Kanade with OpenCV's default window (21x21) and pyramid (3 levels) on the POI
// centres; averaged like pxflow's estimate: more than MINCOUNT tracked points or no flow; with
// HF on, per axis, the mean of the (unquantised) vectors whose half-pixel bin lies within 2 bins
// of the histogram's first maximum; with HF off, the plain mean.
class LucasKanadeEstimator {
 public:
  LucasKanadeEstimator(std::vector<opencv::Point2f> points, const Params& p);
  FlowEstimate estimate(const Frame& prev, const Frame& next);

 private:
  std::vector<opencv::Point2f> points_, moved_;
  std::vector<unsigned char> status_;
  Params p_;
};

// DIS flow, PRESET_ULTRAFAST, the dense field's mean over every pixel.
class DisEstimator {
 public:
  DisEstimator();
  ~DisEstimator();
  DisEstimator(const DisEstimator&) = delete;
  DisEstimator& operator=(const DisEstimator&) = delete;
  FlowEstimate estimate(const Frame& prev, const Frame& next);

 private:
  const opencv::Api& cv_;
  opencv::DisFlow* dis_;
};

// The histogram-window mean of one axis (exposed for the tests): values in pixels.
double histogram_window_mean(const std::vector<double>& values);

}  // namespace pxflow::accuracy
