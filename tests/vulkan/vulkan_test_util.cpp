#include "vulkan_test_util.hpp"

#include <catch2/catch.hpp>

#include "errors.hpp"
#include "exactness.hpp"
#include "frame_io.hpp"
#include "sample_data.hpp"

namespace pxflow::test {
namespace {

// "64x64 S=4 B=8", the parameters a mismatch line names.
std::string setting_of(const Params& p) {
  return std::to_string(p.width) + "x" + std::to_string(p.height) +
         " S=" + std::to_string(p.search_radius) + " B=" + std::to_string(p.blocks);
}

OwnedPair crop(const Frame& a, const Frame& b, const std::string& name, int w, int h) {
  OwnedPair op;
  op.name = name;
  op.width = w ? w : a.width;
  op.height = h ? h : a.height;
  for (int y = 0; y < op.height; ++y) {
    op.prev.insert(op.prev.end(), a.pixels.begin() + y * a.width,
                   a.pixels.begin() + y * a.width + op.width);
    op.next.insert(op.next.end(), b.pixels.begin() + y * b.width,
                   b.pixels.begin() + y * b.width + op.width);
  }
  return op;
}

}  // namespace

std::unique_ptr<VulkanBackend> make_vulkan(const VulkanConfig& config) {
  try {
    return std::make_unique<VulkanBackend>(config);
  } catch (const BackendError& e) {
    FAIL("the build enables Vulkan but the backend cannot run here: " << e.what());
  }
  return nullptr;
}

void expect_exact(VulkanBackend& backend, std::span<const FramePair> views,
                  std::span<const std::string> names, const Params& p) {
  const Comparison c = check_exact(
      {"vulkan", "vulkan-corpus", setting_of(p)}, views, names, p,
      [&](std::span<const FramePair> pairs, const Params& params, std::span<PoiRecord> out) {
        OpCounts counts;
        backend.run(pairs, params, out, counts);
      },
      10);
  INFO(c.mismatches << " mismatches\n" << c.text());
  CHECK(c.ok());
}

void expect_exact(VulkanBackend& backend, const std::vector<OwnedPair>& pairs, const Params& p) {
  std::vector<FramePair> views;
  std::vector<std::string> names;
  for (const auto& op : pairs) {
    views.push_back(op.view());
    names.push_back(op.name);
  }
  expect_exact(backend, views, names, p);
}

Params make_params(const std::string& name, int width, int height, int search_radius, int blocks) {
  Params p = profile(name);
  p.width = width;
  p.height = height;
  if (search_radius > 0) p.search_radius = search_radius;
  if (blocks > 0) p.blocks = blocks;
  validate(p);
  return p;
}

std::vector<OwnedPair> real_pairs(int w, int h) {
  const std::string dir = std::string(kSampleDataDir) + "/";
  std::vector<OwnedPair> out;
  for (const std::string name : {"rubberwhale", "basketball"}) {
    const Frame a = load_frame(dir + name + "1.png", std::nullopt);
    const Frame b = load_frame(dir + name + "2.png", std::nullopt);
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    REQUIRE(a.width >= w);
    REQUIRE(a.height >= h);
    out.push_back(crop(a, b, "real/" + name, w, h));
  }
  return out;
}

std::vector<OwnedPair> random_pairs(int w, int h, int search_radius, int n,
                                    std::uint64_t first_seed) {
  std::vector<OwnedPair> out;
  for (int i = 0; i < n; ++i) out.push_back(random_pair(w, h, search_radius, first_seed + i));
  return out;
}

}  // namespace pxflow::test
