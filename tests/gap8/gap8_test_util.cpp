#include "gap8_test_util.hpp"

#include <optional>

#include "frame_io.hpp"
#include "sample_data.hpp"

namespace pxflow::test {

std::vector<OwnedPair> gap8_real_pairs(int w, int h) {
  const std::string dir = std::string(kSampleDataDir) + "/";
  std::vector<OwnedPair> out;
  for (const std::string name : {"rubberwhale", "basketball"}) {
    const Frame a = load_frame(dir + name + "1.png", std::nullopt);
    const Frame b = load_frame(dir + name + "2.png", std::nullopt);
    OwnedPair pair{"real/" + name, w, h, {}, {}};
    const int x0 = (a.width - w) / 2, y0 = (a.height - h) / 2;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        pair.prev.push_back(a.view().at(x0 + x, y0 + y));
        pair.next.push_back(b.view().at(x0 + x, y0 + y));
      }
    out.push_back(std::move(pair));
  }
  return out;
}

std::vector<OwnedPair> gap8_corpus(const Params& p, int n_random, std::uint64_t seed) {
  std::vector<OwnedPair> out;
  for (int i = 0; i < n_random; ++i)
    out.push_back(random_pair(p.width, p.height, p.search_radius, seed + i));
  for (OwnedPair& h : hostile_pairs(p.width, p.height, p.search_radius))
    out.push_back(std::move(h));
  for (OwnedPair& r : gap8_real_pairs(p.width, p.height)) out.push_back(std::move(r));
  return out;
}

}  // namespace pxflow::test
