#include "draw_flow.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "errors.hpp"
#include "grid.hpp"
#include "opencv_module.hpp"
#include "output_plan.hpp"

namespace pxflow {
namespace {

// How the frame maps to the picture: `scale` screen pixels per frame pixel (so that a 64x64
// frame becomes 640x640), `gain` for POI vectors too short to see at that scale, and
// `flow_gain` for the one frame-flow arrow, which has the whole picture to itself.
struct Layout {
  int scale;
  int gain;
  int flow_gain;
};

Layout layout(const Params& p, std::span<const PoiRecord> records) {
  const int scale = std::max(1, 640 / std::max(p.width, p.height));
  // The 90th percentile of the accepted vectors spans 80% of the spacing between POIs, so that
  // typical vectors are long enough to read and few overlap their neighbours (1x to 16x).
  std::vector<double> lengths;
  for (const auto& r : records)
    if (r.status == kAccepted) lengths.push_back(std::hypot(r.hx, r.hy) / 2.0);
  int gain = 1;
  if (!lengths.empty()) {
    const auto p90 = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() * 9 / 10);
    std::nth_element(lengths.begin(), p90, lengths.end());
    const auto axis = grid_axis(p.width, p);
    const int spacing = axis.size() > 1 ? axis[1] - axis[0] : 8;
    if (*p90 > 0) gain = std::clamp(static_cast<int>(0.8 * spacing / *p90), 1, 16);
  }
  // The frame flow: S pixels would span half the picture's smaller side.
  const int side = std::min(p.width, p.height);
  return {scale, gain, std::max(gain, side / (2 * p.search_radius))};
}

}  // namespace

void check_png_name(const std::string& option, const std::string& path) {
  if (path.empty()) throw InputError(option + " needs a file name (got an empty one)");
  // Standard output, a device or a pipe has no name to keep (--draw - | display, /dev/null).
  std::error_code ec;
  const auto st = std::filesystem::status(path, ec);
  if (descriptor_of(path) >= 0 || std::filesystem::is_character_file(st) ||
      std::filesystem::is_fifo(st))
    return;
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return std::tolower(ch); });
  if (ext != ".png")
    throw InputError(option + " " + path + ": the picture is written as PNG; name it *.png");
}

std::string flow_png(const FrameView& prev, const Params& p, std::span<const PoiRecord> records,
                     const FrameResult& result, const DrawCaption& caption) {
  const Layout l = layout(p, records);
  const opencv::FlowPicture picture{prev,           records,         result,
                                    l.scale,        l.gain,          l.flow_gain,
                                    caption.frames, caption.backend, caption.profile};
  std::vector<std::uint8_t> png;
  std::string error;
  opencv_api().draw_flow_png(picture, png, error);
  if (!error.empty()) throw OutputError("cannot draw the picture: " + error);
  return {reinterpret_cast<const char*>(png.data()), png.size()};
}

}  // namespace pxflow
