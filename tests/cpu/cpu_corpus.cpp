#include "cpu_corpus.hpp"

#include <cstdio>
#include <cstring>

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

Group make_group(std::string setting, const Params& p, int seeds) {
  Group g{"synthetic", std::move(setting), p, {}};
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
  auto whole = [&](const char* setting, const Params& p) {
    groups.push_back({"real/" + name, setting, p, {make_case(name, w, h, w, prev, next, w)}});
  };
  whole("px4flow-64", sized("px4flow-64", w, h, 0, 0));
  whole("px4flow-head", sized("px4flow-head", w, h, 0, 0));
  whole("S=7 B=32", sized("px4flow-64", w, h, 7, 32));
  Group crops{"real/" + name + " 64x64 crops", "px4flow-64", sized("px4flow-64", 64, 64, 0, 0), {}};
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

bool check_group(const std::string& who, const Group& g, const BatchRun& run) {
  std::vector<FramePair> pairs;
  std::vector<std::string> names;
  for (const Case& c : g.cases) pairs.push_back(c.view()), names.push_back(c.name);
  const Comparison cmp = check_exact({who, g.name, g.setting}, pairs, names, g.params, run);
  for (const std::string& line : cmp.lines) std::printf("%s\n", line.c_str());
  return cmp.ok();
}

}  // namespace pxflow::cpu_test
