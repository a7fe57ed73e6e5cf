// cpu_path_check ISA: the masked-path test. CTest runs it once per compiled ISA with
// PXFLOW_DISABLE masking every stronger one, so that the dispatcher row `cpu` must choose ISA;
// it then checks `cpu` (all cores) and the row named ISA (one thread) against ref-original on
// the whole corpus: synthetic pairs, hostile pairs and the real frames of opencv-doc.
// Exit 0 when every case matches, 1 on any mismatch, 77 (CTest SKIP_RETURN_CODE) when this CPU
// lacks ISA.
#include <cstdio>
#include <filesystem>
#include <string>

#include "cpu_corpus.hpp"
#include "errors.hpp"
#include "frame_io.hpp"
#include "isa_mask.hpp"
#include "registry.hpp"

namespace pxflow::cpu_test {
namespace {

constexpr int kSkip = 77;

Params for_frame(const char* profile_name, int width, int height, int radius, int blocks) {
  Params p = profile(profile_name);
  p.width = width;
  p.height = height;
  if (radius > 0) p.search_radius = radius;
  if (blocks > 0) p.blocks = blocks;
  validate(p);
  return p;
}

// The real frames at their full size (px4flow-64, px4flow-head, S=7 B=32) and as 64x64 crops
// that keep the full frame's stride.
std::vector<Group> real_corpus(const std::string& dir) {
  std::vector<Group> groups;
  for (const char* name : {"rubberwhale", "basketball"}) {
    const std::string a = dir + "/" + name + "1.png", b = dir + "/" + name + "2.png";
    if (!std::filesystem::exists(a) || !std::filesystem::exists(b)) {
      std::printf("note: %s not found, real frames %s not checked (install opencv-doc)\n",
                  a.c_str(), name);
      continue;
    }
    const Frame prev = load_frame(a, std::nullopt), next = load_frame(b, std::nullopt);
    const int w = prev.width, h = prev.height;
    auto whole = [&](const std::string& group, const Params& p) {
      groups.push_back(
          {group, p, {make_case(name, w, h, w, prev.pixels.data(), next.pixels.data(), w)}});
    };
    whole(std::string(name) + " px4flow-64", for_frame("px4flow-64", w, h, 0, 0));
    whole(std::string(name) + " px4flow-head", for_frame("px4flow-head", w, h, 0, 0));
    whole(std::string(name) + " S=7 B=32", for_frame("px4flow-64", w, h, 7, 32));
    Group crops{std::string(name) + " 64x64 crops", for_frame("px4flow-64", 64, 64, 0, 0), {}};
    for (int y = 0; y + 64 <= h; y += 90)
      for (int x = 0; x + 64 <= w; x += 100) {
        const std::size_t at = static_cast<std::size_t>(y) * w + x;
        crops.cases.push_back(
            make_case(std::string(name) + " crop at " + std::to_string(x) + "," + std::to_string(y),
                      64, 64, w, prev.pixels.data() + at, next.pixels.data() + at, w));
      }
    groups.push_back(std::move(crops));
  }
  return groups;
}

BatchRun backend_run(const std::string& row_name, int threads) {
  return [row_name, threads](std::span<const FramePair> pairs, const Params& p,
                             std::span<PoiRecord> out) {
    auto backend = find_backend(row_name).create(BackendOptions{threads, {}});
    OpCounts counts;
    backend->run(pairs, p, out, counts);
  };
}

int run(const std::string& isa) {
  // Whether the CPU has it, regardless of the mask this test was started with.
  if (const std::string why = cpu::isa_unavailable(isa);
      !why.empty() && why.find("masked") == std::string::npos) {
    std::printf("skipped: %s (%s)\n", isa.c_str(), why.c_str());
    return kSkip;
  }
  const std::string chosen = cpu::best_isa();
  if (chosen != isa) {
    std::printf("FAIL dispatcher chose '%s', expected '%s' (PXFLOW_DISABLE mask)\n", chosen.c_str(),
                isa.c_str());
    return 1;
  }
  std::vector<Group> groups = synthetic_corpus(120);
  for (Group& g : real_corpus(PXFLOW_OPENCV_DATA)) groups.push_back(std::move(g));
  int failed = 0, total = 0;
  for (const Group& g : groups) {
    total += 2 * static_cast<int>(g.cases.size());
    failed += check_group("cpu(" + isa + ")", g, backend_run("cpu", 0));
    failed += check_group(isa, g, backend_run(isa, 1));
  }
  std::printf("%s: %d of %d case runs failed (%zu groups)\n", isa.c_str(), failed, total,
              groups.size());
  return failed == 0 ? 0 : 1;
}

}  // namespace
}  // namespace pxflow::cpu_test

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: cpu_path_check ISA\n");
    return 2;
  }
  try {
    return pxflow::cpu_test::run(argv[1]);
  } catch (const std::exception& e) {
    std::printf("FAIL %s: %s\n", argv[1], e.what());
    return 1;
  }
}
