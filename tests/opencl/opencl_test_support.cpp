#include "opencl_test_support.hpp"

#include <catch2/catch.hpp>
#include <map>
#include <memory>
#include <stdexcept>

#include "exactness.hpp"
#include "frame_io.hpp"
#include "registry.hpp"
#include "sample_data.hpp"

namespace pxflow::test {
namespace {

struct Shape {
  Params params;
  int random_pairs;
  int window_step;  // spacing of the windows cut from the real frames
};

Shape shape_of(const std::string& profile) {
  if (profile != "px4flow-64" && profile != "px4flow-head")
    throw std::invalid_argument("opencl tests: no corpus for profile " + profile);
  return {pxflow::profile(profile), 300, 61};
}

// Real frames stay loaded for the whole run: corpus pairs are views into them.
const Frame& sample(const std::string& name) {
  static std::map<std::string, std::unique_ptr<Frame>> frames;
  auto& slot = frames[name];
  if (!slot)
    slot = std::make_unique<Frame>(
        load_frame(std::string(kSampleDataDir) + "/" + name + ".png", std::nullopt));
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

}  // namespace

void require_opencl_device() {
  const std::string why = find_backend("opencl").probe();
  INFO("the opencl backend cannot run here: "
       << why << " (install pocl-opencl-icd, or configure with -DPXFLOW_WITH_OPENCL=OFF)");
  REQUIRE(why.empty());
}

const Corpus& corpus(const std::string& profile) {
  static std::map<std::string, std::unique_ptr<Corpus>> cache;
  auto& slot = cache[profile];
  if (!slot) slot = std::make_unique<Corpus>(build_corpus(profile));
  return *slot;
}

const ReferenceAnswer& reference(const std::string& profile) {
  static std::map<std::string, std::unique_ptr<ReferenceAnswer>> cache;
  auto& slot = cache[profile];
  if (!slot) {
    const Corpus& c = corpus(profile);
    slot = std::make_unique<ReferenceAnswer>(reference_answer(c.pairs, c.params));
  }
  return *slot;
}

Comparison compare(OpenclBackend& backend, const std::string& profile, const std::string& who) {
  const Corpus& c = corpus(profile);
  const ReferenceAnswer& want = reference(profile);
  std::vector<PoiRecord> got = sentinel_records(want.records.size());
  OpCounts counts;
  backend.run(c.pairs, c.params, got, counts);  // an exception fails the test with its message
  return compare_with_reference({who, "opencl-corpus", profile}, c.names, c.params, want, got, 10);
}

}  // namespace pxflow::test
