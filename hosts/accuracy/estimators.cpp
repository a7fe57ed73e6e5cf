#include "estimators.hpp"

#include <cmath>
#include <map>

#include "errors.hpp"
#include "estimate.hpp"
#include "grid.hpp"
#include "registry.hpp"

namespace pxflow::accuracy {
namespace {

FrameView view_of(const cv::Mat& m) {
  return {m.cols, m.rows, static_cast<std::ptrdiff_t>(m.step[0]), m.ptr<std::uint8_t>(0)};
}

}  // namespace

PxflowEstimator::PxflowEstimator(const std::string& backend_name, const BackendOptions& options,
                                 const Params& p)
    : p_(p), records_(poi_count(p)) {
  backend_ = open_backend_for(find_backend(backend_name), options, p);
  // An 8x8 block whose top-left pixel is (x, y) has its centre at (x + 3.5, y + 3.5).
  for (const Poi& poi : poi_grid(p)) centres_.emplace_back(poi.x + 3.5f, poi.y + 3.5f);
}

FlowEstimate PxflowEstimator::estimate(const cv::Mat& prev, const cv::Mat& next) {
  const FramePair pair{view_of(prev), view_of(next)};
  check_batch({&pair, 1}, p_, records_);
  OpCounts counts;
  backend_->run({&pair, 1}, p_, records_, counts);
  const FrameResult r = estimate_flow(records_, p_);
  return {{r.flow_x, r.flow_y}, r.quality > 0};
}

double histogram_window_mean(const std::vector<double>& values) {
  std::map<long, int> hist;  // half-pixel bin -> count, ascending
  for (double v : values) ++hist[std::lround(2 * v)];
  long peak = 0;
  int most = -1;
  for (const auto& [bin, n] : hist)
    if (n > most) most = n, peak = bin;  // strict: the first maximum, as SPEC §5
  double sum = 0;
  int used = 0;
  for (double v : values)
    if (std::labs(std::lround(2 * v) - peak) <= 2) sum += v, ++used;
  return used ? sum / used : 0.0;
}

LucasKanadeEstimator::LucasKanadeEstimator(std::vector<cv::Point2f> points, const Params& p)
    : points_(std::move(points)), p_(p) {}

FlowEstimate LucasKanadeEstimator::estimate(const cv::Mat& prev, const cv::Mat& next) {
  cv::calcOpticalFlowPyrLK(prev, next, points_, moved_, status_, error_);
  std::vector<double> xs, ys;
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (status_[i]) {
      xs.push_back(moved_[i].x - points_[i].x);
      ys.push_back(moved_[i].y - points_[i].y);
    }
  if (static_cast<int>(xs.size()) <= p_.min_count) return {{0, 0}, false};
  if (p_.hist_filter) return {{histogram_window_mean(xs), histogram_window_mean(ys)}, true};
  double sx = 0, sy = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) sx += xs[i], sy += ys[i];
  return {{sx / xs.size(), sy / ys.size()}, true};
}

DisEstimator::DisEstimator()
    : dis_(cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST)) {}

FlowEstimate DisEstimator::estimate(const cv::Mat& prev, const cv::Mat& next) {
  dis_->calc(prev, next, field_);
  const cv::Scalar mean = cv::mean(field_);
  return {{mean[0], mean[1]}, true};
}

}  // namespace pxflow::accuracy
