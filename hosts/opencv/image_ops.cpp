// Known motion and the camera's ills (the check corpus, the accuracy pairs), and the optical flow
// of OpenCV that pxflow accuracy compares against.
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "opencv_mat.hpp"

namespace pxflow::opencv {

struct DisFlow {
  cv::Ptr<cv::DISOpticalFlow> dis =
      cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST);
  cv::Mat field;
};

Frame warp_affine(const Frame& src, const Affine& m) {
  const cv::Mat a = mat_of(src.view());
  cv::Mat M(2, 3, CV_64F), b;
  for (int i = 0; i < 6; ++i) M.at<double>(i / 3, i % 3) = m[i];
  cv::warpAffine(a, b, M, a.size(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
  return frame_of(b);
}

void gaussian_blur(Frame& f, double sigma) {
  cv::Mat m = mat_of(f.view()), b;
  cv::GaussianBlur(m, b, cv::Size(0, 0), sigma);
  f = frame_of(b);
}

void gain_offset(Frame& f, double gain, double offset) {
  cv::Mat m = mat_of(f.view()), b;
  m.convertTo(b, CV_8U, gain, offset);
  f = frame_of(b);
}

void add_noise(Frame& f, double sigma, std::uint64_t seed) {
  const cv::Mat m = mat_of(f.view());
  cv::Mat noise(m.size(), CV_16S), wide, b;
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0, sigma);
  m.convertTo(wide, CV_16S);
  wide += noise;
  wide.convertTo(b, CV_8U);  // saturates
  f = frame_of(b);
}

void lucas_kanade(const FrameView& prev, const FrameView& next, const std::vector<Point2f>& points,
                  std::vector<Point2f>& moved, std::vector<unsigned char>& found) {
  std::vector<cv::Point2f> from, to;
  for (const Point2f& p : points) from.emplace_back(p.x, p.y);
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(mat_of(prev), mat_of(next), from, to, found, error);
  moved.clear();
  for (const cv::Point2f& p : to) moved.push_back({p.x, p.y});
}

DisFlow* create_dis() { return new DisFlow; }

std::array<double, 2> dis_mean_flow(DisFlow* dis, const FrameView& prev, const FrameView& next) {
  dis->dis->calc(mat_of(prev), mat_of(next), dis->field);
  const cv::Scalar mean = cv::mean(dis->field);
  return {mean[0], mean[1]};
}

void destroy_dis(DisFlow* dis) { delete dis; }

}  // namespace pxflow::opencv
