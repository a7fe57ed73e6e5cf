#include "cpu_corpus.hpp"

#include <cstdio>
#include <cstring>

#include "grid.hpp"
#include "kernel.hpp"
#include "synthetic.hpp"

namespace pxflow::cpu_test {
namespace {

Params sized(const char* profile_name, int width, int height, int radius, int blocks) {
  Params p = profile(profile_name);
  p.width = width;
  p.height = height;
  if (radius > 0) p.search_radius = radius;
  if (blocks > 0) p.blocks = blocks;
  validate(p);
  return p;
}

Group make_group(std::string name, const Params& p, int seeds) {
  Group g{std::move(name), p, {}};
  const int w = p.width, h = p.height, S = p.search_radius;
  for (int s = 1; s <= seeds; ++s) {
    const OwnedPair op = random_pair(w, h, S, static_cast<std::uint64_t>(s));
    const std::ptrdiff_t stride = (s % 3 == 0) ? w + 13 : w;  // every third: an odd stride
    g.cases.push_back(make_case(op.name, w, h, stride, op.prev.data(), op.next.data(), w));
  }
  for (const OwnedPair& op : hostile_pairs(w, h, S))
    g.cases.push_back(make_case(op.name, w, h, w, op.prev.data(), op.next.data(), w));
  return g;
}

void print_record(const char* who, const PoiRecord& r) {
  std::printf(
      "      %-12s st=%u feat=%u d=(%d,%d) sad=%u dir=%u sub=[%u %u %u %u %u %u %u %u] h=(%d,%d)\n",
      who, r.status, r.feature, r.dx, r.dy, r.sad, r.dir, r.sub[0], r.sub[1], r.sub[2], r.sub[3],
      r.sub[4], r.sub[5], r.sub[6], r.sub[7], r.hx, r.hy);
}

}  // namespace

Case make_case(std::string name, int width, int height, std::ptrdiff_t stride,
               const std::uint8_t* prev, const std::uint8_t* next, std::ptrdiff_t src_stride) {
  Case c{std::move(name), width, height, stride, {}, {}};
  const std::size_t bytes = static_cast<std::size_t>(stride * (height - 1) + width);
  c.prev.assign(bytes, 0x5A);
  c.next.assign(bytes, 0x5A);
  for (int y = 0; y < height; ++y) {
    std::memcpy(c.prev.data() + y * stride, prev + y * src_stride, static_cast<std::size_t>(width));
    std::memcpy(c.next.data() + y * stride, next + y * src_stride, static_cast<std::size_t>(width));
  }
  return c;
}

std::vector<Group> synthetic_corpus(int seeds) {
  std::vector<Group> groups;
  groups.push_back(make_group("px4flow-64", sized("px4flow-64", 64, 64, 0, 0), seeds));
  groups.push_back(make_group("px4flow-head", sized("px4flow-head", 64, 64, 0, 0), seeds));
  groups.push_back(make_group("320x240 S=7 B=16", sized("px4flow-64", 320, 240, 7, 16), 4));
  groups.push_back(make_group("96x80 S=13 B=3", sized("px4flow-64", 96, 80, 13, 3), seeds / 4));
  groups.push_back(make_group("90x90 S=31 B=2", sized("px4flow-head", 90, 90, 31, 2), 3));
  return groups;
}

std::vector<Group> real_groups(const std::string& name, int width, int height,
                               const std::uint8_t* prev, const std::uint8_t* next) {
  const int w = width, h = height;
  std::vector<Group> groups;
  auto whole = [&](const char* what, const Params& p) {
    groups.push_back({name + " " + what, p, {make_case(name, w, h, w, prev, next, w)}});
  };
  whole("px4flow-64", sized("px4flow-64", w, h, 0, 0));
  whole("px4flow-head", sized("px4flow-head", w, h, 0, 0));
  whole("S=7 B=32", sized("px4flow-64", w, h, 7, 32));
  Group crops{name + " 64x64 crops", sized("px4flow-64", 64, 64, 0, 0), {}};
  for (int y = 0; y + 64 <= h; y += 90)
    for (int x = 0; x + 64 <= w; x += 100) {
      const std::size_t at = static_cast<std::size_t>(y) * w + x;
      crops.cases.push_back(
          make_case(name + " crop at " + std::to_string(x) + "," + std::to_string(y), 64, 64, w,
                    prev + at, next + at, w));
    }
  groups.push_back(std::move(crops));
  return groups;
}

int check_group(const std::string& who, const Group& g, const BatchRun& run) {
  const std::size_t per_pair = poi_count(g.params);
  std::vector<FramePair> pairs;
  for (const Case& c : g.cases) pairs.push_back(c.view());
  std::vector<PoiRecord> expected(pairs.size() * per_pair), got(pairs.size() * per_pair);
  std::memset(got.data(), 0xA5, got.size() * sizeof(PoiRecord));  // catches unwritten records
  for (std::size_t n = 0; n < pairs.size(); ++n) {
    OpCounts ignored;
    reference_flow(RefVariant::kOriginal, pairs[n], g.params,
                   std::span(expected).subspan(n * per_pair, per_pair), ignored);
  }
  run(pairs, g.params, got);
  int failed = 0;
  for (std::size_t n = 0; n < pairs.size(); ++n) {
    for (std::size_t i = 0; i < per_pair; ++i) {
      const PoiRecord& e = expected[n * per_pair + i];
      const PoiRecord& a = got[n * per_pair + i];
      if (std::memcmp(&e, &a, sizeof(PoiRecord)) == 0) continue;
      std::printf("FAIL %s %s %s: POI %zu (x=%u, y=%u) differs from ref-original\n", who.c_str(),
                  g.name.c_str(), g.cases[n].name.c_str(), i, e.x, e.y);
      print_record("ref-original", e);
      print_record(who.c_str(), a);
      ++failed;
      break;
    }
  }
  return failed;
}

}  // namespace pxflow::cpu_test
