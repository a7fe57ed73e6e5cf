// `pxflow flow --draw FILE`: a PNG that decodes at the expected size with the status colours in
// it, at 64x64 (enlarged 10x) and at full size; bad --draw paths are one line with exit 2.
#include <catch2/catch.hpp>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "run_program.hpp"
#include "sample_frames.hpp"
#include "truth_pairs.hpp"

using pxflow::test::kData;
using pxflow::test::run_pxflow;

namespace {

// Pixels close to the drawing's colour for accepted POIs (BGR 90, 230, 90) and frame flow.
int count_colour(const cv::Mat& img, cv::Vec3b colour) {
  int n = 0;
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x)
      n += cv::norm(img.at<cv::Vec3b>(y, x), colour, cv::NORM_L1) < 30;
  return n;
}

}  // namespace

TEST_CASE("flow --draw writes a PNG of the expected size with vectors in it", "[accuracy][draw]") {
  pxflow::test::TempDir dir;
  // A 64x64 camera pair with known motion, as pxflow accuracy makes them.
  const auto images = pxflow::accuracy::load_source_images(kData);
  const auto pair =
      pxflow::accuracy::make_truth_pairs(images, pxflow::accuracy::Geometry::kCamera64, 1, 3)[0];
  const auto mat = [](const pxflow::Frame& f) {
    return cv::Mat(f.height, f.width, CV_8UC1, const_cast<std::uint8_t*>(f.pixels.data()));
  };
  REQUIRE(cv::imwrite(dir.path("a.png"), mat(pair.prev)));
  REQUIRE(cv::imwrite(dir.path("b.png"), mat(pair.next)));

  struct Case {
    std::string prev, next, out;
    cv::Size expected;
  };
  const Case cases[] = {
      {dir.path("a.png"),
       dir.path("b.png"),
       dir.path("small.png"),
       {640, 640 + 84}},  // 64x64 x10, caption below
      {kData + "/rubberwhale1.png",
       kData + "/rubberwhale2.png",
       dir.path("full.png"),
       {640, 388 + 84}},
  };
  for (const Case& c : cases) {
    INFO(c.prev);
    const auto r = run_pxflow({"flow", "--draw", c.out, c.prev, c.next});
    INFO("stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("flow ") != std::string::npos);  // the summary is still printed
    const cv::Mat img = cv::imread(c.out, cv::IMREAD_COLOR);
    REQUIRE(!img.empty());
    CHECK(img.size() == c.expected);
    CHECK(count_colour(img, {90, 230, 90}) > 20);  // accepted vectors
    CHECK(count_colour(img, {255, 230, 0}) > 20);  // the frame flow arrow
  }
}

TEST_CASE("bad --draw paths: one line, exit 2, nothing written", "[accuracy][draw][errors]") {
  pxflow::test::TempDir dir;
  const std::string a = kData + "/rubberwhale1.png", b = kData + "/rubberwhale2.png";
  for (const auto& [path, needle] : std::vector<std::pair<std::string, std::string>>{
           {dir.path("out.jpg"), "name it *.png"},
           {dir.path("missing/out.png"), "no such directory"},
           {dir.path(""), "name it *.png"},
       }) {
    INFO(path);
    const auto r = run_pxflow({"flow", "--draw", path, a, b});
    INFO("stderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err_lines() == 1);
    CHECK(r.err.find(needle) != std::string::npos);
    CHECK(r.out.empty());
  }
  std::filesystem::create_directory(dir.path("dir.png"));
  const auto r = run_pxflow({"flow", "--draw", dir.path("dir.png"), a, b});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("is a directory") != std::string::npos);
  CHECK(!std::filesystem::exists(dir.path("out.jpg")));
}
