// The flow picture (`pxflow flow --draw`, the report's pictures): the first frame enlarged and
// dimmed, each POI with its vector coloured by status, the frame flow as one bold arrow, and a
// caption; encoded as PNG. The layout (scale and gains) is decided by hosts/io/draw_flow.cpp.
#include <algorithm>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "opencv_mat.hpp"

namespace pxflow::opencv {
namespace {

// BGR colours: accepted green, rejected orange, dropped grey, the frame flow cyan.
const cv::Scalar kColourAccepted(90, 230, 90), kColourRejected(40, 150, 255),
    kColourDropped(170, 170, 170);
const cv::Scalar kColourFlow(255, 230, 0), kShadow(0, 0, 0), kText(240, 240, 240);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr int kCaptionHeight = 84;

cv::Mat background(const FrameView& prev, int scale) {
  cv::Mat gray(prev.height, prev.width, CV_8UC1);
  for (int y = 0; y < prev.height; ++y)
    std::copy_n(prev.row(y), prev.width, gray.ptr<std::uint8_t>(y));
  gray.convertTo(gray, CV_8U, 0.6, 25);  // dimmed so that the vectors stand out
  cv::Mat big, bgr;
  cv::resize(gray, big, cv::Size(), scale, scale, cv::INTER_NEAREST);  // pixels stay pixels
  cv::cvtColor(big, bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

void arrow(cv::Mat& img, cv::Point2d from, cv::Point2d to, const cv::Scalar& colour,
           int thickness) {
  const double length = cv::norm(to - from);
  if (length < 1.0) {
    cv::circle(img, from, thickness + 1, colour, cv::FILLED, cv::LINE_AA);
    return;
  }
  const double tip = std::min(0.4, 10.0 * thickness / length);
  cv::arrowedLine(img, from, to, kShadow, thickness + 2, cv::LINE_AA, 0, tip);
  cv::arrowedLine(img, from, to, colour, thickness, cv::LINE_AA, 0, tip);
}

void draw_poi(cv::Mat& img, const PoiRecord& r, const FlowPicture& l) {
  const double s = l.scale;
  const cv::Point2d centre((r.x + 3.5) * s + s / 2, (r.y + 3.5) * s + s / 2);
  const int thin = l.scale >= 4 ? 2 : 1;
  if (8 * l.scale >= 40) {  // blocks big enough to outline without hiding the frame
    const cv::Scalar& c = r.status == kAccepted   ? kColourAccepted
                          : r.status == kRejected ? kColourRejected
                                                  : kColourDropped;
    cv::rectangle(img, cv::Rect(r.x * l.scale, r.y * l.scale, 8 * l.scale, 8 * l.scale), c * 0.55,
                  1);
  }
  if (r.status == kDropped) {
    cv::circle(img, centre, 1 + thin, kColourDropped * 0.7, 1, cv::LINE_AA);
  } else if (r.status == kRejected) {  // where its best (rejected) integer match was
    arrow(img, centre, centre + cv::Point2d(r.dx, r.dy) * (s * l.gain), kColourRejected, 1);
    const double m = 2.0 + thin;
    cv::line(img, centre - cv::Point2d(m, m), centre + cv::Point2d(m, m), kColourRejected, thin,
             cv::LINE_AA);
    cv::line(img, centre - cv::Point2d(m, -m), centre + cv::Point2d(m, -m), kColourRejected, thin,
             cv::LINE_AA);
  } else {
    arrow(img, centre, centre + cv::Point2d(r.hx, r.hy) * (s * l.gain / 2.0), kColourAccepted,
          thin);
  }
}

std::string printf_string(const char* fmt, double a, double b) {
  char buf[128];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

// Text, then a coloured swatch per status with its count, left to right.
void draw_caption(cv::Mat& img, int top, const FrameResult& result,
                  std::span<const PoiRecord> records, const FlowPicture& l) {
  int counts[3] = {0, 0, 0};
  for (const auto& r : records) ++counts[r.status];
  const std::string flow =
      printf_string("flow x %+.2f px, y %+.2f px", result.flow_x, result.flow_y);
  cv::putText(img, flow + "   quality " + std::to_string(result.quality), {10, top + 22}, kFont,
              0.55, kText, 1, cv::LINE_AA);
  const std::string who = l.backend + ", " + l.profile;
  const int who_width = cv::getTextSize(who, kFont, 0.45, 1, nullptr).width;
  cv::putText(img, who, {img.cols - 10 - who_width, top + 22}, kFont, 0.45, kText * 0.75, 1,
              cv::LINE_AA);
  int x = 10;
  auto item = [&](const cv::Scalar& colour, const std::string& label) {
    cv::rectangle(img, cv::Rect(x, top + 36, 14, 14), colour, cv::FILLED);
    cv::putText(img, label, {x + 20, top + 48}, kFont, 0.45, kText, 1, cv::LINE_AA);
    x += 30 + cv::getTextSize(label, kFont, 0.45, 1, nullptr).width;
  };
  item(kColourAccepted, std::to_string(counts[kAccepted]) + " accepted");
  item(kColourRejected, std::to_string(counts[kRejected]) + " rejected");
  item(kColourDropped, std::to_string(counts[kDropped]) + " dropped");
  item(kColourFlow, "frame flow");
  const std::string note = l.frames + "   (vectors drawn x" + std::to_string(l.gain) +
                           ", frame flow x" + std::to_string(l.flow_gain) + ")";
  cv::putText(img, note, {10, top + 72}, kFont, 0.4, kText * 0.75, 1, cv::LINE_AA);
}

}  // namespace

void draw_flow_png(const FlowPicture& l, std::vector<std::uint8_t>& png, std::string& error) {
  try {
    const cv::Mat frame = background(l.prev, l.scale);
    cv::Mat img(frame.rows + kCaptionHeight, std::max(frame.cols, 640), CV_8UC3,
                cv::Scalar(32, 32, 32));
    frame.copyTo(img(cv::Rect(0, 0, frame.cols, frame.rows)));
    for (const auto& r : l.records) draw_poi(img, r, l);
    const cv::Point2d centre(frame.cols / 2.0, frame.rows / 2.0);
    const cv::Point2d flow(l.result.flow_x, l.result.flow_y);
    arrow(img, centre, centre + flow * (l.scale * l.flow_gain), kColourFlow,
          std::max(3, l.scale / 2));
    draw_caption(img, frame.rows, l.result, l.records, l);
    if (!cv::imencode(".png", img, png)) error = "cannot encode the picture as PNG";
  } catch (const cv::Exception& e) {
    error = std::string("cannot draw the picture: ") + e.what();
  }
}

}  // namespace pxflow::opencv
