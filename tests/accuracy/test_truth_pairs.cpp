// The ground truth `pxflow accuracy` rests on: the motion a pair claims is the motion in it, at
// both geometries (including the binning and the centre of rotation), and the averaging that LK
// shares with pxflow's estimate.
#include <catch2/catch.hpp>
#include <opencv2/imgproc.hpp>

#include "estimators.hpp"
#include "sample_frames.hpp"
#include "truth_pairs.hpp"

using namespace pxflow::accuracy;
using pxflow::test::kData;

namespace {

cv::Mat mat(const pxflow::Frame& f) {
  return cv::Mat(f.height, f.width, CV_8UC1, const_cast<std::uint8_t*>(f.pixels.data())).clone();
}

cv::Matx23d matx(const pxflow::opencv::Affine& m) { return cv::Matx23d(m.data()); }

// 1 - the normalised correlation of next with prev moved by `motion`, over the interior: 0 for
// a perfect explanation whatever the brightness change, about 1 for an unrelated image.
double residual(const TruthPair& t, const cv::Matx23d& motion) {
  const cv::Mat prev = mat(t.prev), next = mat(t.next);
  cv::Mat moved, score;
  cv::warpAffine(prev, moved, cv::Mat(motion), prev.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  const int m = prev.cols / 8;
  const cv::Rect inner(m, m, prev.cols - 2 * m, prev.rows - 2 * m);
  cv::matchTemplate(moved(inner), next(inner), score, cv::TM_CCOEFF_NORMED);
  return 1.0 - score.at<float>(0, 0);
}

// The same motion with its displacement at the frame's centre reversed: what a sign error in
// the truth (or in the centre of rotation) would claim.
cv::Matx23d reversed(const TruthPair& t) {
  const Point2d d = t.displacement_at((t.prev.width - 1) / 2.0, (t.prev.height - 1) / 2.0);
  cv::Matx23d wrong = matx(t.motion);
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
      const double right = residual(t, matx(t.motion)), wrong = residual(t, reversed(t));
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
    CHECK(a[i].next.pixels == b[i].next.pixels);
    CHECK((a[i].prev.width == 64 && a[i].prev.height == 64));
  }
  const auto window = make_truth_pairs(images, Geometry::kWindow320, 1, 5)[0].prev;
  CHECK((window.width == 320 && window.height == 240));
}

TEST_CASE("displacement_at is the affine motion minus the point", "[accuracy][truth]") {
  TruthPair t;
  t.motion = {1, 0, 1.5, 0, 1, -0.25};
  CHECK(t.displacement_at(10, 20) == Point2d{1.5, -0.25});
  t.motion = {0, -1, 0, 1, 0, 0};  // 90 degrees about the origin
  CHECK(t.displacement_at(1, 0) == Point2d{-1, 1});
}

TEST_CASE("LK's average: the histogram peak's window, like pxflow's HF", "[accuracy][lk]") {
  // Half-pixel bins: 1.0 and 1.1 -> bin 2, 0.9 -> 2, 2.2 -> 4 (inside +-2 bins), 5.0 -> 10 (out).
  CHECK(histogram_window_mean({1.0, 1.1, 0.9, 2.2, 5.0}) == Approx((1.0 + 1.1 + 0.9 + 2.2) / 4));
  // Two equal peaks: the first (lowest bin) wins, as SPEC §5's strict scan.
  CHECK(histogram_window_mean({-3.0, -3.0, 3.0, 3.0}) == Approx(-3.0));
  CHECK(histogram_window_mean({}) == 0.0);
}
