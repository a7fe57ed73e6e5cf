#include "estimators.hpp"

#include <cmath>
#include <map>

#include "errors.hpp"
#include "estimate.hpp"
#include "grid.hpp"
#include "opencv_module.hpp"
#include "registry.hpp"

namespace pxflow::accuracy {
PxflowEstimator::PxflowEstimator(const std::string& backend_name, const BackendOptions& options,
                                 const Params& p)
    : p_(p), records_(poi_count(p)) {
  backend_ = open_backend_for(find_backend(backend_name), options, p);
  // An 8x8 block whose top-left pixel is (x, y) has its centre at (x + 3.5, y + 3.5).
  for (const Poi& poi : poi_grid(p)) centres_.emplace_back(poi.x + 3.5f, poi.y + 3.5f);
}

FlowEstimate PxflowEstimator::estimate(const Frame& prev, const Frame& next) {
  const FramePair pair{prev.view(), next.view()};
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

LucasKanadeEstimator::LucasKanadeEstimator(std::vector<opencv::Point2f> points, const Params& p)
    : points_(std::move(points)), p_(p) {}

FlowEstimate LucasKanadeEstimator::estimate(const Frame& prev, const Frame& next) {
  opencv_api().lucas_kanade(prev.view(), next.view(), points_, moved_, status_);
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

DisEstimator::DisEstimator() : cv_(opencv_api()), dis_(cv_.create_dis()) {}

DisEstimator::~DisEstimator() { cv_.destroy_dis(dis_); }

FlowEstimate DisEstimator::estimate(const Frame& prev, const Frame& next) {
  const auto [x, y] = cv_.dis_mean_flow(dis_, prev.view(), next.view());
  return {{x, y}, true};
}

}  // namespace pxflow::accuracy
