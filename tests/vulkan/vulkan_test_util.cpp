#include "vulkan_test_util.hpp"

#include <catch2/catch.hpp>
#include <cstring>
#include <sstream>

#include "errors.hpp"
#include "frame_io.hpp"
#include "grid.hpp"
#include "kernel.hpp"

namespace pxflow::test {
namespace {

std::string describe(const PoiRecord& r) {
  std::ostringstream s;
  s << "(x " << r.x << " y " << r.y << " status " << int(r.status) << " pad0 " << int(r.pad0)
    << " feature " << r.feature << " dx " << int(r.dx) << " dy " << int(r.dy) << " sad " << r.sad
    << " dir " << int(r.dir) << " pad1 " << int(r.pad1) << " sub";
  for (auto v : r.sub) s << ' ' << v;
  s << " hx " << int(r.hx) << " hy " << int(r.hy) << ")";
  return s.str();
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

void expect_exact(VulkanBackend& backend, const std::vector<OwnedPair>& pairs, const Params& p) {
  const std::size_t per_pair = poi_count(p);
  std::vector<FramePair> views;
  for (const auto& op : pairs) views.push_back(op.view());
  std::vector<PoiRecord> got(views.size() * per_pair), want(got.size());
  std::memset(got.data(), 0xA5, got.size() * sizeof(PoiRecord));  // catches unwritten records
  std::memset(want.data(), 0x5A, want.size() * sizeof(PoiRecord));
  OpCounts counts;
  backend.run(views, p, got, counts);
  std::size_t bad = 0;
  for (std::size_t n = 0; n < views.size(); ++n) {
    std::span<PoiRecord> ref(want.data() + n * per_pair, per_pair);
    reference_flow(RefVariant::kOriginal, views[n], p, ref, counts);
    for (std::size_t i = 0; i < per_pair; ++i) {
      const PoiRecord& a = got[n * per_pair + i];
      const PoiRecord& b = ref[i];
      if (std::memcmp(&a, &b, sizeof a) == 0) continue;
      if (++bad <= 5)
        UNSCOPED_INFO(pairs[n].name << " " << p.width << "x" << p.height << " S=" << p.search_radius
                                    << " B=" << p.blocks << " poi " << i << ": vulkan "
                                    << describe(a) << " ref-original " << describe(b));
    }
  }
  CHECK(bad == 0);
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
  const std::string dir = "/usr/share/doc/opencv-doc/examples/data/";
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
