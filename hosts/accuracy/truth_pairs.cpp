#include "truth_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "counted.hpp"
#include "errors.hpp"
#include "frame_io.hpp"
#include "frame_ops.hpp"
#include "interrupt.hpp"
#include "opencv_module.hpp"
#include "sample_data.hpp"
#include "synthetic.hpp"
#include "video_file.hpp"

namespace pxflow::accuracy {
namespace {

// Real images from Debian's opencv-doc, each at least 336x256 so that both geometries fit.
const char* const kImages[] = {"rubberwhale1.png", "basketball1.png", "baboon.jpg",
                               "fruits.jpg",       "building.jpg",    "home.jpg"};

// What happens between the two frames; ranges are scaled per geometry (see ranges()).
struct Kind {
  const char* name;
  bool rotate, zoom;
  double noise_sigma, blur_sigma;
  bool brightness;
};
const Kind kKinds[] = {
    {"translate", false, false, 0, 0, false},
    {"translate+noise", false, false, 3.0, 0, false},
    {"translate+blur", false, false, 0, 0.8, false},
    {"translate+brightness", false, false, 0, 0, true},
    {"rotate+translate", true, false, 0, 0, false},
    {"zoom+translate", false, true, 0, 0, false},
    {"all-ills", true, true, 2.0, 0.6, true},
};

struct Ranges {
  double shift, angle_deg, zoom;  // uniform in [-shift, shift], [-angle, angle], 1 +- zoom
};
Ranges ranges(Geometry g) {
  // Inside what px4flow-64 (S=4) and the 320x240 setting (S=7) can see, corners included.
  return g == Geometry::kCamera64 ? Ranges{3.0, 2.0, 0.02} : Ranges{6.0, 1.0, 0.01};
}

double uniform(Rng& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng.next() >> 11) * 0x1.0p-53;
}

// Rotation by angle (degrees, counter-clockwise on screen as OpenCV's) and scale about (cx, cy),
// then a translation: all in double, so the truth is exact.
opencv::Affine affine(double cx, double cy, double angle_deg, double scale, double tx, double ty) {
  const double a = angle_deg * std::numbers::pi / 180.0;
  const double al = scale * std::cos(a), be = scale * std::sin(a);
  return {al, be, (1 - al) * cx - be * cy + tx, -be, al, be * cx + (1 - al) * cy + ty};
}

// Where the geometry's frame lies in the full image: binning factor and top-left corner in the
// binned image, and the frame size.
struct Placement {
  int factor, x0, y0, width, height;
};
Placement place(const Frame& full, Geometry g) {
  if (g == Geometry::kWindow320)
    return {1, (full.width - 320) / 2, (full.height - 240) / 2, 320, 240};
  const int f = (full.width >= 256 && full.height >= 256) ? 4 : 2;  // as check_corpus.cpp's camera
  return {f, (full.width / f - 64) / 2, (full.height / f - 64) / 2, 64, 64};
}

Frame capture(const Frame& full, const Placement& pl) {
  const Frame binned = bin(full, pl.factor);
  return crop(binned, pl.x0, pl.y0, pl.width, pl.height);
}

TruthPair make_pair(const SourceImage& img, const Kind& kind, Geometry g, std::uint64_t seed) {
  Rng rng(seed * 0x9E3779B97F4A7C15ull + 1);
  const Ranges r = ranges(g);
  const double tx = uniform(rng, -r.shift, r.shift), ty = uniform(rng, -r.shift, r.shift);
  const double angle = kind.rotate ? uniform(rng, -r.angle_deg, r.angle_deg) : 0.0;
  const double scale = kind.zoom ? 1.0 + uniform(rng, -r.zoom, r.zoom) : 1.0;
  const Placement pl = place(img.gray, g);
  const double f = pl.factor;
  // The frame's centre, in frame pixels and in full-image pixels (a binned pixel i covers full
  // pixels f*i .. f*i+f-1, so its centre is f*i + (f-1)/2).
  const double cx = (pl.width - 1) / 2.0, cy = (pl.height - 1) / 2.0;
  const double fcx = f * (pl.x0 + cx) + (f - 1) / 2, fcy = f * (pl.y0 + cy) + (f - 1) / 2;
  // The sensor sees the scene move by f times the motion in binned pixels.
  const opencv::Api& cv = opencv_api();
  const Frame moved = cv.warp_affine(img.gray, affine(fcx, fcy, angle, scale, f * tx, f * ty));

  TruthPair t{kind.name + std::string("/") + img.name + "/seed=" + std::to_string(seed), kind.name,
              capture(img.gray, pl), capture(moved, pl), affine(cx, cy, angle, scale, tx, ty)};
  if (kind.blur_sigma > 0) cv.gaussian_blur(t.next, kind.blur_sigma);
  if (kind.brightness) {
    // The offset is drawn first: the order GCC evaluated the two draws in when they were the
    // arguments of one call, so every seed still makes the pair it made before.
    const double offset = uniform(rng, -20, 20);
    cv.gain_offset(t.next, uniform(rng, 0.8, 1.2), offset);
  }
  if (kind.noise_sigma > 0) {
    cv.add_noise(t.prev, kind.noise_sigma, seed * 2);
    cv.add_noise(t.next, kind.noise_sigma, seed * 2 + 1);
  }
  return t;
}

}  // namespace

Point2d TruthPair::displacement_at(double x, double y) const {
  const double qx = motion[0] * x + motion[1] * y + motion[2];
  const double qy = motion[3] * x + motion[4] * y + motion[5];
  return {qx - x, qy - y};
}

std::vector<SourceImage> load_source_images(const std::string& data_dir) {
  std::vector<SourceImage> out;
  for (const char* name : kImages) {
    const std::string path = data_dir + "/" + name;
    if (!std::filesystem::exists(path))
      throw InputError(path + ": no such file " + kSampleDataHint);
    const Frame f = load_frame(path, std::nullopt);
    if (f.width < 336 || f.height < 256)
      throw InputError(path + ": " + std::to_string(f.width) + "x" + std::to_string(f.height) +
                       " is smaller than the 336x256 the accuracy pairs need");
    out.push_back({name, f});
  }
  return out;
}

std::vector<TruthPair> make_truth_pairs(const std::vector<SourceImage>& images, Geometry g,
                                        int count, std::uint64_t first_seed) {
  std::vector<TruthPair> out;
  constexpr std::size_t kinds = std::size(kKinds);
  for (int n = 0; n < count; ++n) {
    stop_if_interrupted(std::to_string(n) + " of " + std::to_string(count) + " pairs made");
    const auto i = static_cast<std::size_t>(n);
    // Kinds cycle fastest, images change every pass, so each image meets every kind.
    out.push_back(
        make_pair(images[(i / kinds) % images.size()], kKinds[i % kinds], g, first_seed + i));
  }
  return out;
}

std::vector<VideoPair> video_pairs(const std::string& path, int count) {
  if (!std::filesystem::exists(path)) throw InputError(path + ": no such file " + kSampleDataHint);
  // Count the frames by reading them (the container's own count can be wrong), then reopen.
  int frames = 0;
  for (VideoFile counting(path); counting.skip();) ++frames;
  VideoFile video(path);
  const int step = std::max(2, frames / std::max(1, count));
  const std::string name = std::filesystem::path(path).filename().string();
  std::vector<VideoPair> out;
  Frame gray, previous;
  for (int n = 0; static_cast<int>(out.size()) < count && video.read(gray); ++n) {
    if (n % step == 1 && !previous.pixels.empty())
      out.push_back({name + "#" + std::to_string(n - 1), previous, gray});
    if (n % step == 0) previous = gray;
  }
  if (out.size() < static_cast<std::size_t>(count))
    throw InputError(path + ": has fewer than " + std::to_string(count) + " frame pairs " +
                     counted(step, "frame") + " apart");
  return out;
}

}  // namespace pxflow::accuracy
