#include "accuracy_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "check_corpus.hpp"
#include "errors.hpp"
#include "estimators.hpp"
#include "interrupt.hpp"
#include "opencv_module.hpp"
#include "params.hpp"
#include "progress.hpp"
#include "registry.hpp"
#include "truth_pairs.hpp"

namespace pxflow::accuracy {
namespace {

// "S=7 B=32": the parameters a setting's name gives beside its size or profile.
std::string s_b_text(const Params& p) {
  return "S=" + std::to_string(p.search_radius) + " B=" + std::to_string(p.blocks);
}

using Clock = std::chrono::steady_clock;

// Per method: the error and the time of every frame, and how many frames had a flow.
struct Samples {
  std::vector<double> errors, micros;
  int valid = 0;
};

double percentile95(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(v.size())));
  return v[std::max<std::size_t>(rank, 1) - 1];  // nearest rank
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

MethodRow summarise(const std::string& method, const Samples& s, bool has_error) {
  MethodRow row{method,          static_cast<int>(s.micros.size()), s.valid, has_error, 0, 0,
                median(s.micros)};
  if (has_error) {
    double sum = 0;
    for (double e : s.errors) sum += e;
    row.mean_error = sum / static_cast<double>(s.errors.size());
    row.p95_error = percentile95(s.errors);
  }
  return row;
}

// Times one estimate with the steady clock and records its validity.
template <class Estimator>
FlowEstimate timed(Estimator& e, const Frame& prev, const Frame& next, Samples& s) {
  const auto t0 = Clock::now();
  const FlowEstimate est = e.estimate(prev, next);
  const auto t1 = Clock::now();
  s.micros.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
  s.valid += est.valid;
  return est;
}

// The three estimators for one frame size, built once and reused for every pair.
struct Methods {
  PxflowEstimator px;
  LucasKanadeEstimator lk;
  DisEstimator dis;
  std::string px_name;
  Methods(const AccuracyOptions& o, const Params& p)
      : px(o.backend, o.backend_options, p),
        lk(px.poi_centres(), p),
        px_name("pxflow (" + o.backend + ")") {}
};

Point2d mean_point(const std::vector<opencv::Point2f>& pts) {
  Point2d sum;
  for (const auto& q : pts) sum.x += q.x, sum.y += q.y;
  const double n = static_cast<double>(pts.size());
  return {sum.x / n, sum.y / n};
}

// The Euclidean distance, computed as cv::norm of the difference computes it (not std::hypot,
// which may differ in the last bit).
double distance(const Point2d& a, const Point2d& b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return std::sqrt(dx * dx + dy * dy);
}

// Synthetic pairs: every method's error against the true motion. The truth for pxflow and LK is
// the motion at the mean POI centre (= the mean motion over the POI centres, the motion being
// affine); for DIS, averaged over every pixel, the motion at the frame's centre.
std::vector<SetRows> truth_sets(const std::string& set, const std::string& setting, const Params& p,
                                const std::vector<TruthPair>& pairs, const AccuracyOptions& o) {
  Methods m(o, p);
  const Point2d poi_mean = mean_point(m.px.poi_centres());
  const Point2d centre{(p.width - 1) / 2.0, (p.height - 1) / 2.0};
  std::map<std::string, Samples[3]> by_kind;  // "" = all pairs
  for (const TruthPair& t : pairs) {
    const std::string done = set + ": " + std::to_string(by_kind[""][0].errors.size()) + " of " +
                             std::to_string(pairs.size()) + " pairs";
    stop_if_interrupted(done);
    progress("accuracy: " + done);
    const Point2d at_pois = t.displacement_at(poi_mean.x, poi_mean.y);
    const Point2d at_centre = t.displacement_at(centre.x, centre.y);
    Samples* all = by_kind[""];
    const FlowEstimate px = timed(m.px, t.prev, t.next, all[0]);
    const FlowEstimate lk = timed(m.lk, t.prev, t.next, all[1]);
    const FlowEstimate dis = timed(m.dis, t.prev, t.next, all[2]);
    const double errors[3] = {distance(px.flow, at_pois), distance(lk.flow, at_pois),
                              distance(dis.flow, at_centre)};
    for (int k = 0; k < 3; ++k) all[k].errors.push_back(errors[k]);
    if (!o.by_kind) continue;
    Samples* kind = by_kind[t.kind];
    for (int k = 0; k < 3; ++k) {
      kind[k].errors.push_back(errors[k]);
      kind[k].micros.push_back(all[k].micros.back());
    }
    kind[0].valid += px.valid, kind[1].valid += lk.valid, kind[2].valid += dis.valid;
  }
  std::vector<SetRows> out;
  for (const auto& [kind, s] : by_kind) {
    SetRows rows{kind.empty() ? set : set + ", " + kind, setting, "true motion", {}};
    rows.rows = {summarise(m.px_name, s[0], true), summarise("LK", s[1], true),
                 summarise("DIS", s[2], true)};
    out.insert(kind.empty() ? out.begin() : out.end(), std::move(rows));
  }
  return out;
}

// Real consecutive frames: agreement of pxflow and LK with DIS; DIS's own row has no error.
SetRows agreement_set(const std::string& video, const AccuracyOptions& o) {
  const auto pairs = video_pairs(o.data_dir + "/" + video, o.video_pairs);
  const Params p = video_setting(pairs.front().prev.width, pairs.front().prev.height);
  Methods m(o, p);
  Samples s[3];
  for (const VideoPair& v : pairs) {
    const std::string done = video + ": " + std::to_string(s[0].errors.size()) + " of " +
                             std::to_string(pairs.size()) + " pairs";
    stop_if_interrupted(done);
    progress("accuracy: " + done);
    const FlowEstimate px = timed(m.px, v.prev, v.next, s[0]);
    const FlowEstimate lk = timed(m.lk, v.prev, v.next, s[1]);
    const FlowEstimate dis = timed(m.dis, v.prev, v.next, s[2]);
    s[0].errors.push_back(distance(px.flow, dis.flow));
    s[1].errors.push_back(distance(lk.flow, dis.flow));
  }
  const std::string size = std::to_string(p.width) + "x" + std::to_string(p.height);
  return {video + " " + size + " (real, consecutive frames)",
          video_setting_name(p),
          "DIS (agreement, not ground truth)",
          {summarise(m.px_name, s[0], true), summarise("LK", s[1], true),
           summarise("DIS", s[2], false)}};
}

// The setting of each set of pairs run_accuracy makes, with its name ("320x240 S=7 B=16").
std::vector<std::pair<std::string, Params>> problems(const AccuracyOptions& o) {
  auto named = [](const Params& p) {
    return std::pair{std::to_string(p.width) + "x" + std::to_string(p.height) + " " + s_b_text(p),
                     p};
  };
  std::vector<std::pair<std::string, Params>> out{named(profile(kDefaultProfile)),
                                                  named(check_settings()[2].second)};
  if (o.video_pairs > 0)
    for (const char* video : kVideos) {
      const auto first = video_pairs(o.data_dir + "/" + video, 1);
      if (!first.empty())
        out.push_back(named(video_setting(first.front().prev.width, first.front().prev.height)));
    }
  return out;
}

}  // namespace

Params video_setting(int width, int height) {
  Params p = profile(kDefaultProfile);
  p.width = width, p.height = height;
  p.search_radius = 7, p.blocks = 32;  // the full-size setting of pxflow check's real frames
  validate(p);
  return p;
}

std::string video_setting_name(const Params& p) {
  return std::string(kDefaultProfile) + " " + s_b_text(p);
}

void require_backend_runs(const AccuracyOptions& o) {
  const BackendRow& row = find_backend(o.backend);
  for (const auto& [name, p] : problems(o)) {
    try {
      (void)open_backend_for(row, o.backend_options, p);
    } catch (const InputError& e) {
      throw InputError(std::string(e.what()) + " (the accuracy pairs at " + name +
                       "); choose another --backend");
    }
  }
}

AccuracyReport run_accuracy(const AccuracyOptions& o) {
  opencv_api().set_threads(o.threads);
  AccuracyReport r;
  const auto images = load_source_images(o.data_dir);  // missing data is named first
  require_backend_runs(o);
  for (const auto& img : images) r.images.push_back(img.name);
  auto add = [&](std::vector<SetRows> sets) {
    for (auto& s : sets) r.sets.push_back(std::move(s));
  };
  const auto camera = make_truth_pairs(images, Geometry::kCamera64, o.pairs, o.seed * 100000);
  add(truth_sets("synthetic, camera 64x64 (4x4 binned)", std::string(kDefaultProfile),
                 profile(kDefaultProfile), camera, o));
  const auto [window_setting, window_params] = check_settings()[2];  // 320x240 S=7 B=16
  const auto window = make_truth_pairs(images, Geometry::kWindow320, std::max(1, o.pairs / 4),
                                       o.seed * 100000 + 50000);
  add(truth_sets("synthetic, 320x240 window", window_setting, window_params, window, o));
  if (o.video_pairs > 0)
    for (const char* video : kVideos) r.sets.push_back(agreement_set(video, o));
  progress("");  // clears the live line
  return r;
}

}  // namespace pxflow::accuracy
