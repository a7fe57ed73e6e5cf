// The ground truth `pxflow accuracy` rests on: the motion a pair claims is the motion in it, at
// both geometries (including the binning and the centre of rotation), and the averaging that LK
// shares with pxflow's estimate.
#include <catch2/catch.hpp>
#include <opencv2/imgproc.hpp>

#include "estimators.hpp"
#include "sample_data.hpp"
#include "truth_pairs.hpp"

using namespace pxflow::accuracy;

namespace {

const std::string kData = pxflow::kSampleDataDir;

// 1 - the normalised correlation of next with prev moved by `motion`, over the interior: 0 for
// a perfect explanation whatever the brightness change, about 1 for an unrelated image.
double residual(const TruthPair& t, const cv::Matx23d& motion) {
  cv::Mat moved, score;
  cv::warpAffine(t.prev, moved, cv::Mat(motion), t.prev.size(), cv::INTER_LINEAR,
                 cv::BORDER_REPLICATE);
  const int m = t.prev.cols / 8;
  const cv::Rect inner(m, m, t.prev.cols - 2 * m, t.prev.rows - 2 * m);
  cv::matchTemplate(moved(inner), t.next(inner), score, cv::TM_CCOEFF_NORMED);
  return 1.0 - score.at<float>(0, 0);
}

// The same motion with its displacement at the frame's centre reversed: what a sign error in
// the truth (or in the centre of rotation) would claim.
cv::Matx23d reversed(const TruthPair& t) {
  const cv::Point2d d = t.displacement_at((t.prev.cols - 1) / 2.0, (t.prev.rows - 1) / 2.0);
  cv::Matx23d wrong = t.motion;
  wrong(0, 2) -= 2 * d.x, wrong(1, 2) -= 2 * d.y;
  return wrong;
}

}  // namespace

TEST_CASE("the claimed motion explains each pair, a sign flip does not", "[accuracy][truth]") {
  const auto images = load_source_images(kData);
  REQUIRE(images.size() >= 3);
  for (Geometry g : {Geometry::kCamera64, Geometry::kWindow320}) {
    // 7 kinds in turn: the first 7 pairs cover translate, noise, blur, brightness, rotate, zoom,
    // all.
    const auto pairs = make_truth_pairs(images, g, 7, 11);
    for (const TruthPair& t : pairs) {
      INFO(t.name);
      const double right = residual(t, t.motion), wrong = residual(t, reversed(t));
      CHECK(right < 0.02);  // measured: at most 0.006, with noise and blur
      CHECK(wrong > right * 3 + 0.01);
    }
  }
}

TEST_CASE("pairs are reproducible from their seed and sized as the geometry says",
          "[accuracy][truth]") {
  const auto images = load_source_images(kData);
  const auto a = make_truth_pairs(images, Geometry::kCamera64, 3, 5);
  const auto b = make_truth_pairs(images, Geometry::kCamera64, 3, 5);
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].name == b[i].name);
    CHECK(cv::norm(a[i].next, b[i].next, cv::NORM_INF) == 0);
    CHECK(a[i].prev.size() == cv::Size(64, 64));
  }
  CHECK(make_truth_pairs(images, Geometry::kWindow320, 1, 5)[0].prev.size() == cv::Size(320, 240));
}

TEST_CASE("displacement_at is the affine motion minus the point", "[accuracy][truth]") {
  TruthPair t;
  t.motion = cv::Matx23d(1, 0, 1.5, 0, 1, -0.25);
  CHECK(t.displacement_at(10, 20) == cv::Point2d(1.5, -0.25));
  t.motion = cv::Matx23d(0, -1, 0, 1, 0, 0);  // 90 degrees about the origin
  CHECK(t.displacement_at(1, 0) == cv::Point2d(-1, 1));
}

TEST_CASE("LK's average: the histogram peak's window, like pxflow's HF", "[accuracy][lk]") {
  // Half-pixel bins: 1.0 and 1.1 -> bin 2, 0.9 -> 2, 2.2 -> 4 (inside +-2 bins), 5.0 -> 10 (out).
  CHECK(histogram_window_mean({1.0, 1.1, 0.9, 2.2, 5.0}) == Approx((1.0 + 1.1 + 0.9 + 2.2) / 4));
  // Two equal peaks: the first (lowest bin) wins, as SPEC §5's strict scan.
  CHECK(histogram_window_mean({-3.0, -3.0, 3.0, 3.0}) == Approx(-3.0));
  CHECK(histogram_window_mean({}) == 0.0);
}
