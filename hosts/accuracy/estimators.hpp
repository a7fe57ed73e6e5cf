// The three ways to get one frame's motion that `pxflow accuracy` compares: pxflow's frame flow
// through a registry backend, OpenCV's pyramidal Lucas-Kanade on pxflow's POIs averaged the way
// pxflow's estimate averages, and OpenCV's DIS flow (ultrafast preset) averaged over the frame.
#pragma once
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/video/tracking.hpp>
#include <string>
#include <vector>

#include "backend.hpp"
#include "params.hpp"
#include "record.hpp"

namespace pxflow::accuracy {

struct FlowEstimate {
  cv::Point2d flow;    // pixels per frame, content motion right/down positive
  bool valid = false;  // pxflow: quality > 0; LK: more than MINCOUNT points tracked; DIS: always
};

// pxflow's frame flow (SPEC §5) from one backend's records.
class PxflowEstimator {
 public:
  PxflowEstimator(const std::string& backend_name, const BackendOptions& options, const Params& p);
  FlowEstimate estimate(const cv::Mat& prev, const cv::Mat& next);
  // Where the averages of the other methods are taken: the centres of the POI blocks.
  const std::vector<cv::Point2f>& poi_centres() const { return centres_; }
  const Params& params() const { return p_; }

 private:
  std::unique_ptr<Backend> backend_;
  Params p_;
  std::vector<cv::Point2f> centres_;
  std::vector<PoiRecord> records_;
};

// cv::calcOpticalFlowPyrLK with OpenCV's default window (21x21) and pyramid (3 levels) on the POI
// centres; averaged like pxflow's estimate: more than MINCOUNT tracked points or no flow; with
// HF on, per axis, the mean of the (unquantised) vectors whose half-pixel bin lies within 2 bins
// of the histogram's first maximum; with HF off, the plain mean.
class LucasKanadeEstimator {
 public:
  LucasKanadeEstimator(std::vector<cv::Point2f> points, const Params& p);
  FlowEstimate estimate(const cv::Mat& prev, const cv::Mat& next);

 private:
  std::vector<cv::Point2f> points_, moved_;
  std::vector<unsigned char> status_;
  std::vector<float> error_;
  Params p_;
};

// cv::DISOpticalFlow, PRESET_ULTRAFAST, the dense field's mean over every pixel.
class DisEstimator {
 public:
  DisEstimator();
  FlowEstimate estimate(const cv::Mat& prev, const cv::Mat& next);
  const cv::Mat& last_field() const { return field_; }

 private:
  cv::Ptr<cv::DISOpticalFlow> dis_;
  cv::Mat field_;
};

// The histogram-window mean of one axis (exposed for the tests): values in pixels.
double histogram_window_mean(const std::vector<double>& values);

}  // namespace pxflow::accuracy
