#include "check_corpus.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <numbers>

#include "errors.hpp"
#include "frame_io.hpp"
#include "frame_ops.hpp"
#include "grid.hpp"
#include "kernel.hpp"
#include "opencv_module.hpp"
#include "video_file.hpp"

namespace pxflow {
namespace {

OwnedPair owned(std::string name, const Frame& a, const Frame& b) {
  return {std::move(name), a.width, a.height, a.pixels, b.pixels};
}

// The PX4FLOW camera bins its 752x480 sensor 4x4 and reads a 64x64 window from the middle.
Frame px4flow_camera(const Frame& full) {
  const int factor = (full.width >= 256 && full.height >= 256) ? 4 : 2;
  const Frame b = bin(full, factor);
  return crop(b, (b.width - 64) / 2, (b.height - 64) / 2, 64, 64);
}

std::vector<std::pair<std::string, std::pair<Frame, Frame>>> real_pairs(const CorpusOptions& o) {
  std::vector<std::pair<std::string, std::pair<Frame, Frame>>> out;
  auto path = [&](const char* name) {
    const std::string p = o.data_dir + "/" + name;
    if (!std::filesystem::exists(p))
      throw InputError(p + ": real frame missing " + kSampleDataHint);
    return p;
  };
  for (const char* stem : {"rubberwhale", "basketball"})
    out.push_back({stem,
                   {load_frame(path((std::string(stem) + "1.png").c_str()), std::nullopt),
                    load_frame(path((std::string(stem) + "2.png").c_str()), std::nullopt)}});
  for (auto [video, first] :
       {std::pair{"vtest.avi", 0}, {"vtest.avi", 120}, {"tree.avi", 0}, {"tree.avi", 30}}) {
    VideoFile cap(path(video));
    Frame gray[2];
    int n = 0;
    for (; n < first && cap.skip(); ++n) {
    }
    for (; n <= first + 1 && cap.read(gray[n - first]); ++n) {
    }
    if (n <= first + 1)
      throw InputError(std::string(video) + ": cannot read frames " + std::to_string(first) + ".." +
                       std::to_string(first + 1));
    out.push_back({std::string(video) + "#" + std::to_string(first), {gray[0], gray[1]}});
  }
  return out;
}

struct Motion {
  const char* name;
  double tx, ty, angle_deg, scale;
  double noise_sigma, blur_sigma, gain, offset;
};

// OpenCV's getRotationMatrix2D (imgproc/src/imgwarp.cpp): rotation by angle (degrees) and scale
// about (cx, cy), in double from float centre coordinates as OpenCV takes them.
opencv::Affine rotation_matrix(float cx, float cy, double angle_deg, double scale) {
  const double a = angle_deg * (std::numbers::pi / 180);
  const double alpha = std::cos(a) * scale, beta = std::sin(a) * scale;
  return {alpha, beta, (1 - alpha) * cx - beta * cy, -beta, alpha, beta * cx + (1 - alpha) * cy};
}

// Known motion applied with OpenCV (bilinear warp), then the camera's ills.
Frame moved(const Frame& src, const Motion& m, std::uint64_t seed) {
  const opencv::Api& cv = opencv_api();
  opencv::Affine M = rotation_matrix(src.width / 2.0f, src.height / 2.0f, m.angle_deg, m.scale);
  M[2] += m.tx;
  M[5] += m.ty;
  Frame b = cv.warp_affine(src, M);
  if (m.blur_sigma > 0) cv.gaussian_blur(b, m.blur_sigma);
  if (m.gain != 1.0 || m.offset != 0.0) cv.gain_offset(b, m.gain, m.offset);
  if (m.noise_sigma > 0) cv.add_noise(b, m.noise_sigma, seed);
  return b;
}

const Motion kMotions[] = {
    {"translate(+2,-1)", 2, -1, 0, 1, 0, 0, 1, 0},
    {"translate(+1.5,+2)", 1.5, 2, 0, 1, 0, 0, 1, 0},
    {"translate(+0.5,+0.5)", 0.5, 0.5, 0, 1, 0, 0, 1, 0},
    {"translate(-0.3,+0.7)", -0.3, 0.7, 0, 1, 0, 0, 1, 0},
    {"translate(+3.25,-2.75)", 3.25, -2.75, 0, 1, 0, 0, 1, 0},
    {"rotate(2deg)", 0, 0, 2, 1, 0, 0, 1, 0},
    {"rotate(-3deg)", 0, 0, -3, 1, 0, 0, 1, 0},
    {"zoom(1.03)", 0, 0, 0, 1.03, 0, 0, 1, 0},
    {"zoom(0.97)", 0, 0, 0, 0.97, 0, 0, 1, 0},
    {"translate+noise", 1.5, -0.5, 0, 1, 4, 0, 1, 0},
    {"translate+blur", -1, 1.5, 0, 1, 0, 1.0, 1, 0},
    {"translate+brighter", 1, 1, 0, 1, 0, 0, 1.1, 12},
};

// Features exactly at FT - 1, FT and FT + 1 (one bump in a POI's central 4x4), moved by (1, 1).
OwnedPair feature_threshold_pair(const Params& p) {
  const int W = p.width, H = p.height;
  std::vector<std::uint8_t> px(static_cast<std::size_t>(W) * H, 100);
  const auto pois = poi_grid(p);
  // An interior pixel of the 4x4 has 4 neighbours there, an edge pixel 3, a corner 2.
  const int bumps[][3] = {{1, 1, 4}, {1, 0, 3}, {0, 0, 2}};
  for (std::size_t n = 0; n < pois.size(); ++n) {
    const auto [cx, cy, neighbours] = bumps[n % 3];
    const int target = p.feature_threshold + static_cast<int>(n % 5) - 2;  // FT-2 .. FT+2
    const int bump = std::max(1, target / neighbours);
    px[(pois[n].y + 2 + cy) * W + pois[n].x + 2 + cx] =
        static_cast<std::uint8_t>(std::min(255, 100 + bump));
  }
  OwnedPair op{"threshold/feature-near-FT", W, H, px, {}};
  shift_into(px, op.next, W, H, 1, 1, 3);
  return op;
}

// A pair and a VT equal to one POI's best SAD, so that POI sits exactly on the threshold. Where
// no seed gives an accepted POI (a --set feature_threshold that keeps none), the first pair at the
// setting's own VT.
std::pair<OwnedPair, int> sad_threshold_pair(const Params& p, std::uint64_t seed) {
  constexpr int kSeedsTried = 64;
  for (std::uint64_t s = seed; s < seed + kSeedsTried; ++s) {
    OwnedPair op = random_pair(p.width, p.height, p.search_radius, s);
    Params loose = p;
    loose.sad_threshold = 65535;
    std::vector<PoiRecord> recs(poi_count(p));
    OpCounts c;
    reference_flow(RefVariant::kOriginal, op.view(), loose, recs, c);
    for (const auto& r : recs)
      if (r.status == kAccepted && r.sad > 0) {
        op.name = "threshold/sad-at-VT=" + std::to_string(r.sad) + "/seed=" + std::to_string(s);
        return {std::move(op), r.sad};
      }
  }
  OwnedPair op = random_pair(p.width, p.height, p.search_radius, seed);
  op.name = "threshold/sad-none-accepted/seed=" + std::to_string(seed);
  return {std::move(op), p.sad_threshold};
}

Params sized(Params p, int w, int h) {
  p.width = w, p.height = h;
  return p;
}

}  // namespace

bool CheckCase::for_row(const std::string& row) const {
  return rows.empty() || std::find(rows.begin(), rows.end(), row) != rows.end();
}

std::string ParamOverride::options() const {
  std::string o = profile.empty() ? "" : " --profile " + profile;
  for (const std::string& kv : sets) o += " --set " + kv;
  return o;
}

std::optional<Params> ParamOverride::apply(const Params& p, std::string* why_not) const {
  Params q = p;
  if (!profile.empty()) {
    q = pxflow::profile(profile);
    q.width = p.width, q.height = p.height;
  }
  for (const std::string& kv : sets) {
    const std::string_view key = set_param_assignment(q, kv);
    if (key == "width" || key == "height")
      throw InputError("--set " + kv + ": the corpus's cases keep their own frame sizes; " +
                       "check sets every parameter but width and height");
  }
  require_no_gyro_comp(q);
  try {
    validate(q);
  } catch (const InputError& e) {
    if (why_not) *why_not = e.what();
    return std::nullopt;
  }
  return q;
}

void ParamOverride::check() const {
  // On a frame large enough for any radius: what fails here fails on every case.
  Params roomy = pxflow::profile(kDefaultProfile);
  roomy.width = roomy.height = 1024;
  std::string why;
  if (!apply(roomy, &why)) throw InputError(options().substr(1) + ": " + why);
}

std::vector<std::pair<std::string, Params>> check_settings(const ParamOverride& o,
                                                           std::vector<std::string>* dropped) {
  auto big = [](int w, int h, int S, int B) {
    Params p;
    p.width = w, p.height = h, p.search_radius = S, p.blocks = B;
    return p;
  };
  std::vector<std::pair<std::string, Params>> own = {
      {std::string(kDefaultProfile), profile(kDefaultProfile)},
      {"px4flow-head", profile("px4flow-head")},
      {"320x240 S=7 B=16", big(320, 240, 7, 16)},
      {"640x480 S=6 B=32 HF off", [&] {
         Params p = big(640, 480, 6, 32);
         p.hist_filter = false;
         return p;
       }()}};
  if (o.empty()) return own;
  std::vector<std::pair<std::string, Params>> kept;
  for (auto& [setting, p] : own) {
    std::string why;
    if (const auto q = o.apply(p, &why))
      kept.push_back({setting + o.options(), *q});
    else if (dropped)
      dropped->push_back(setting + ": " + why);
  }
  return kept;
}

CheckCase fuzz_case(const std::string& setting, const Params& p, std::uint64_t first_seed,
                    int count) {
  CheckCase c{"random", setting, p, {}};
  for (int n = 0; n < count; ++n)
    c.pairs.push_back(random_pair(p.width, p.height, p.search_radius, first_seed + n));
  return c;
}

namespace {

using RealPairs = std::vector<std::pair<std::string, std::pair<Frame, Frame>>>;

// At each setting: random pairs, the hostile patterns and the two threshold cases.
void add_generated_cases(const CorpusOptions& o, std::vector<CheckCase>& cases,
                         std::vector<std::string>* dropped) {
  const auto settings = check_settings(o.params, dropped);
  for (const auto& [setting, p] : settings) {
    const int w = p.width;
    const int randoms = w == 64 ? 96 : (w <= 320 ? 12 : 4);
    cases.push_back(fuzz_case(setting, p, o.seed * 1000003u, randoms));
    CheckCase hostile{"hostile", setting, p, hostile_pairs(p.width, p.height, p.search_radius)};
    cases.push_back(std::move(hostile));
    CheckCase ft{"threshold/feature", setting, p, {feature_threshold_pair(p)}};
    cases.push_back(std::move(ft));
    auto [vt_pair, vt] = sad_threshold_pair(p, o.seed);
    Params pv = p;
    pv.sad_threshold = vt;
    CheckCase vtc{"threshold/sad", setting + " VT=" + std::to_string(vt), pv, {}};
    vtc.pairs.push_back(std::move(vt_pair));
    cases.push_back(std::move(vtc));
  }
}

// The real frames binned as the camera does (at both profiles), and each at full size.
void add_real_cases(const RealPairs& reals, std::vector<CheckCase>& cases) {
  CheckCase binned64{
      "real/camera-64x64", std::string(kDefaultProfile), profile(kDefaultProfile), {}};
  CheckCase binned_head{"real/camera-64x64", "px4flow-head", profile("px4flow-head"), {}};
  for (const auto& [name, fr] : reals) {
    const Frame a = px4flow_camera(fr.first), b = px4flow_camera(fr.second);
    binned64.pairs.push_back(owned("real/" + name + "/camera-64x64", a, b));
    binned_head.pairs.push_back(owned("real/" + name + "/camera-64x64", a, b));
    // Full size, one case each (frames differ in size): the profile's B and a dense grid.
    Params dense = sized(profile(kDefaultProfile), fr.first.width, fr.first.height);
    cases.push_back(
        {"real/full-size",
         "px4flow-64 " + std::to_string(dense.width) + "x" + std::to_string(dense.height),
         dense,
         {owned("real/" + name + "/full", fr.first, fr.second)}});
    dense.search_radius = 7, dense.blocks = 32;
    cases.push_back({"real/full-size",
                     "S=7 B=32 " + std::to_string(dense.width) + "x" + std::to_string(dense.height),
                     dense,
                     {owned("real/" + name + "/full", fr.first, fr.second)}});
  }
  cases.push_back(std::move(binned64));
  cases.push_back(std::move(binned_head));
}

// Known motion with OpenCV on the camera-like 64x64 frame and on a 320x240 window of `src`.
void add_synthetic_cases(const Frame& src, std::uint64_t seed, std::vector<CheckCase>& cases) {
  const Frame base64 = px4flow_camera(src), base320 = crop(src, 0, 0, 320, 240);
  CheckCase s64{"synthetic/64x64", std::string(kDefaultProfile), profile(kDefaultProfile), {}};
  CheckCase s64h{"synthetic/64x64", "px4flow-head", profile("px4flow-head"), {}};
  const auto [window_setting, window_params] = check_settings()[2];  // 320x240 S=7 B=16
  CheckCase s320{"synthetic/320x240", window_setting, window_params, {}};
  for (const Motion& m : kMotions) {
    s64.pairs.push_back(owned(std::string("synthetic/") + m.name + "/seed=" + std::to_string(seed),
                              base64, moved(base64, m, seed)));
    s64h.pairs.push_back(s64.pairs.back());
    s320.pairs.push_back(owned(std::string("synthetic/") + m.name + "/seed=" + std::to_string(seed),
                               base320, moved(base320, m, seed)));
    ++seed;
  }
  cases.push_back(std::move(s64));
  cases.push_back(std::move(s64h));
  cases.push_back(std::move(s320));
}

// The real and synthetic pairs do not depend on the parameters: their cases (those from
// `generated` on) are overridden once made (the generated ones were made at the overridden
// settings); a case the override does not fit is left out and named in `dropped`.
std::vector<CheckCase> override_frame_cases(std::vector<CheckCase> cases, std::size_t generated,
                                            const ParamOverride& params,
                                            std::vector<std::string>* dropped) {
  std::vector<CheckCase> kept(std::make_move_iterator(cases.begin()),
                              std::make_move_iterator(cases.begin() + generated));
  for (auto c = cases.begin() + generated; c != cases.end(); ++c) {
    std::string why;
    if (const auto q = params.apply(c->params, &why)) {
      c->params = *q;
      c->setting += params.options();
      kept.push_back(std::move(*c));
    } else if (dropped) {
      dropped->push_back(c->name + " " + c->setting + ": " + why);
    }
  }
  return kept;
}

}  // namespace

std::vector<CheckCase> build_check_corpus(const CorpusOptions& o,
                                          std::vector<std::string>* dropped) {
  std::vector<CheckCase> cases;
  add_generated_cases(o, cases, dropped);
  if (!o.real) return cases;
  const std::size_t generated = cases.size();
  const RealPairs reals = real_pairs(o);
  add_real_cases(reals, cases);
  add_synthetic_cases(reals.front().second.first, o.seed, cases);
  if (o.params.empty()) return cases;
  return override_frame_cases(std::move(cases), generated, o.params, dropped);
}

}  // namespace pxflow
