#include "opencl_test_support.hpp"

#include <catch2/catch.hpp>
#include <cstring>
#include <map>
#include <memory>

#include "frame_io.hpp"
#include "grid.hpp"
#include "kernel.hpp"
#include "registry.hpp"

namespace pxflow::test {
namespace {

constexpr const char* kSampleDir = "/usr/share/doc/opencv-doc/examples/data/";
constexpr std::uint8_t kSentinel = 0xA5;

struct Shape {
  Params params;
  int random_pairs;
  int window_step;  // spacing of the windows cut from the real frames
};

Shape shape_of(const std::string& profile) {
  if (profile == "px4flow-64" || profile == "px4flow-head")
    return {pxflow::profile(profile), 300, 61};
  Params p;
  p.search_radius = 7;
  if (profile == "128x128-S31") {  // the largest radius: 63x63 candidates, a 72x72 window
    p.width = 128, p.height = 128, p.search_radius = 31, p.blocks = 4;
    return {p, 20, 200};
  }
  if (profile == "320x240") {
    p.width = 320, p.height = 240, p.blocks = 16;
    return {p, 24, 131};
  }
  p.width = 640, p.height = 480, p.blocks = 32;
  return {p, 3, 1000};
}

// Real frames stay loaded for the whole run: corpus pairs are views into them.
const Frame& sample(const std::string& name) {
  static std::map<std::string, std::unique_ptr<Frame>> frames;
  auto& slot = frames[name];
  if (!slot) slot = std::make_unique<Frame>(load_frame(kSampleDir + name + ".png", std::nullopt));
  return *slot;
}

// Every w x h window of the sample pair `stem`1/2 at multiples of `step`, both directions.
void add_real_windows(Corpus& c, const std::string& stem, int step) {
  const Frame& a = sample(stem + "1");
  const Frame& b = sample(stem + "2");
  const int w = c.params.width, h = c.params.height;
  for (int y = 0; y + h <= a.height; y += step) {
    for (int x = 0; x + w <= a.width; x += step) {
      auto window = [&](const Frame& f) {
        return FrameView{w, h, f.width, f.pixels.data() + y * f.width + x};
      };
      const std::string at = stem + "@" + std::to_string(x) + "," + std::to_string(y);
      c.pairs.push_back({window(a), window(b)});
      c.names.push_back("real/" + at);
      c.pairs.push_back({window(b), window(a)});
      c.names.push_back("real/" + at + "/reversed");
    }
  }
}

Corpus build_corpus(const std::string& profile) {
  const Shape s = shape_of(profile);
  Corpus c{profile, s.params, {}, {}, {}};
  const Params& p = c.params;
  for (int seed = 0; seed < s.random_pairs; ++seed)
    c.owned.push_back(random_pair(p.width, p.height, p.search_radius, 1000 + seed));
  for (auto& pair : hostile_pairs(p.width, p.height, p.search_radius))
    c.owned.push_back(std::move(pair));
  for (const auto& o : c.owned) {
    c.pairs.push_back(o.view());
    c.names.push_back(o.name);
  }
  add_real_windows(c, "rubberwhale", s.window_step);
  add_real_windows(c, "basketball", s.window_step);
  return c;
}

const char* field_at(std::size_t offset) {
  static const char* names[32] = {"x",       "x",  "y",  "y",   "status", "pad0", "feature",
                                  "feature", "dx", "dy", "sad", "sad",    "dir",  "pad1"};
  if (offset < 14) return names[offset];
  return offset < 30 ? "sub" : (offset == 30 ? "hx" : "hy");
}

}  // namespace

void require_opencl_device() {
  const std::string why = find_backend("opencl").probe();
  INFO("the opencl backend cannot run here: "
       << why << " (install pocl-opencl-icd, or configure with -DPXFLOW_WITH_OPENCL=OFF)");
  REQUIRE(why.empty());
}

std::vector<std::string> corpus_profiles() {
  return {"px4flow-64", "px4flow-head", "128x128-S31", "320x240", "640x480"};
}

const Corpus& corpus(const std::string& profile) {
  static std::map<std::string, std::unique_ptr<Corpus>> cache;
  auto& slot = cache[profile];
  if (!slot) slot = std::make_unique<Corpus>(build_corpus(profile));
  return *slot;
}

const std::vector<PoiRecord>& reference_records(const std::string& profile) {
  static std::map<std::string, std::vector<PoiRecord>> cache;
  auto& records = cache[profile];
  if (records.empty()) {
    const Corpus& c = corpus(profile);
    const std::size_t per_pair = poi_count(c.params);
    records.resize(c.pairs.size() * per_pair);
    OpCounts counts;
    for (std::size_t n = 0; n < c.pairs.size(); ++n)
      reference_flow(RefVariant::kOriginal, c.pairs[n], c.params,
                     std::span(records).subspan(n * per_pair, per_pair), counts);
  }
  return records;
}

std::vector<std::string> mismatches(OpenclBackend& backend, const std::string& profile) {
  const Corpus& c = corpus(profile);
  const auto& expected = reference_records(profile);
  std::vector<PoiRecord> got(expected.size());
  std::memset(got.data(), kSentinel, got.size() * sizeof(PoiRecord));
  OpCounts counts;
  backend.run(c.pairs, c.params, got, counts);

  std::vector<std::string> lines;
  const std::size_t per_pair = poi_count(c.params);
  for (std::size_t n = 0; n < got.size(); ++n) {
    const auto* a = reinterpret_cast<const std::uint8_t*>(&got[n]);
    const auto* b = reinterpret_cast<const std::uint8_t*>(&expected[n]);
    if (std::memcmp(a, b, sizeof(PoiRecord)) == 0) continue;
    std::size_t at = 0;
    while (a[at] == b[at]) ++at;
    lines.push_back(c.names[n / per_pair] + " POI " + std::to_string(n % per_pair) + " (" +
                    std::to_string(expected[n].x) + "," + std::to_string(expected[n].y) +
                    "): field " + field_at(at) + " byte " + std::to_string(at) + " is " +
                    std::to_string(a[at]) + ", ref-original has " + std::to_string(b[at]));
  }
  return lines;
}

}  // namespace pxflow::test
