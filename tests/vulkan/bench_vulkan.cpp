// Batch throughput of `vulkan` against the best CPU path in the same run (docs/vulkan.md).
// Not a test: built as `vulkan_bench`, run by hand. Records are checked against ref-original
// before anything is timed. Each point reports wall-clock time per frame pair and process CPU
// time per frame pair (all threads, lavapipe's included), so that a loaded machine does not
// make the comparison meaningless.
//
//   vulkan_bench [--cpu NAME] [--min-time SECONDS] [--only LABEL-PREFIX] [--batches N,N,...]
//
// NAME defaults to the registry row `cpu` (the CPU SIMD dispatcher on all cores) when it is
// compiled in, else `ref-original` split over all cores by this program.
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "errors.hpp"
#include "exactness.hpp"
#include "grid.hpp"
#include "kernel.hpp"
#include "registry.hpp"
#include "synthetic.hpp"

using namespace pxflow;

namespace {

constexpr int kDistinctPairs = 16;  // a batch cycles through these (all POIs textured)

double now(clockid_t clock) {
  timespec ts;
  clock_gettime(clock, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// ref-original on all cores: the batch split into one contiguous slice per core.
class ParallelReference final : public Backend {
 public:
  void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
           OpCounts&) override {
    const std::size_t per = poi_count(p);
    const std::size_t workers = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> threads;
    for (std::size_t w = 0; w < workers; ++w)
      threads.emplace_back([&, w] {
        OpCounts local;
        for (std::size_t n = w; n < pairs.size(); n += workers)
          reference_flow(RefVariant::kOriginal, pairs[n], p, out.subspan(n * per, per), local);
      });
    for (auto& t : threads) t.join();
  }
};

struct Point {
  std::string label;
  Params params;
};

struct Timing {
  double wall_us = 0;  // per frame pair
  double cpu_us = 0;
};

// ref-original's answer for a batch that cycles through the distinct pairs of `distinct`.
ReferenceAnswer cycled(const ReferenceAnswer& distinct, std::size_t batch, std::size_t per) {
  ReferenceAnswer a;
  for (std::size_t n = 0; n < batch; ++n) {
    const auto first = distinct.records.begin() + (n % kDistinctPairs) * per;
    a.records.insert(a.records.end(), first, first + per);
    a.results.push_back(distinct.results[n % kDistinctPairs]);
  }
  return a;
}

// Checks the first run against ref-original through the shared exactness checker (the first
// mismatch line goes to stderr), then repeats for `min_time` the code the backend times
// (Backend::select_timed: vulkan's production shader) after one warm-up run of it.
Timing measure(const std::string& who, Backend& b, const std::vector<FramePair>& views,
               const Params& p, const ReferenceAnswer& distinct, double min_time, bool& exact) {
  const std::size_t per = poi_count(p);
  std::vector<PoiRecord> out = sentinel_records(views.size() * per);
  OpCounts counts;
  b.select_timed(false);
  b.run(views, p, out, counts);
  std::vector<std::string> names;
  for (std::size_t n = 0; n < views.size(); ++n)
    names.push_back("shifted-texture/" + std::to_string(n % kDistinctPairs));
  const Comparison c = compare_with_reference({who, "bench", std::to_string(views.size())}, names,
                                              p, cycled(distinct, views.size(), per), out, 1);
  exact = c.ok();
  if (!exact) std::fprintf(stderr, "%s", c.text().c_str());
  b.select_timed(true);
  b.run(views, p, out, counts);
  int runs = 0;
  const double w0 = now(CLOCK_MONOTONIC), c0 = now(CLOCK_PROCESS_CPUTIME_ID);
  do {
    b.run(views, p, out, counts);
    ++runs;
  } while (now(CLOCK_MONOTONIC) - w0 < min_time);
  const double frames = double(runs) * double(views.size());
  return {(now(CLOCK_MONOTONIC) - w0) * 1e6 / frames,
          (now(CLOCK_PROCESS_CPUTIME_ID) - c0) * 1e6 / frames};
}

std::unique_ptr<Backend> make_cpu(const std::string& name) {
  if (name == "ref-original") return std::make_unique<ParallelReference>();
  return find_backend(name).create({});
}

}  // namespace

int main(int argc, char** argv) {
  std::string cpu_name = "ref-original";
  for (const auto& row : backend_rows())
    if (row.name == "cpu" && row.probe().empty()) cpu_name = "cpu";
  double min_time = 1.0;
  std::string only;
  std::vector<int> batches = {1, 256, 4096};
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--cpu") == 0) cpu_name = argv[i + 1];
    if (std::strcmp(argv[i], "--min-time") == 0) min_time = std::stod(argv[i + 1]);
    if (std::strcmp(argv[i], "--only") == 0) only = argv[i + 1];
    if (std::strcmp(argv[i], "--batches") == 0) {
      batches.clear();
      for (const char* c = argv[i + 1]; *c; c += (*c == ','))
        batches.push_back(std::atoi(c)), c += std::strspn(c, "0123456789");
    }
  }
  try {
    auto vulkan = find_backend("vulkan").create({});
    auto cpu = make_cpu(cpu_name);
    Params large = profile("px4flow-64");
    large.width = 320, large.height = 240, large.search_radius = 7, large.blocks = 16;
    const std::vector<Point> points = {{"px4flow-64 64x64 S=4 B=8", profile("px4flow-64")},
                                       {"320x240 S=7 B=16", large}};
    std::printf("cores %u, cpu = %s%s\n", std::thread::hardware_concurrency(), cpu_name.c_str(),
                cpu_name == "ref-original" ? " (split over all cores)" : " (all cores)");
    std::printf("%-26s %6s  %-8s %12s %12s %12s %10s\n", "problem", "batch", "backend",
                "wall us/pair", "cpu us/pair", "pairs/s", "vs cpu");
    for (const Point& pt : points) {
      if (pt.label.rfind(only, 0) != 0) continue;
      std::vector<OwnedPair> owned;
      std::vector<FramePair> distinct_views;
      for (int n = 0; n < kDistinctPairs; ++n) {
        owned.push_back(shifted_texture_pair(pt.params.width, pt.params.height,
                                             pt.params.search_radius, 0xBE7C4 + n));
        distinct_views.push_back(owned.back().view());
      }
      const ReferenceAnswer expected = reference_answer(distinct_views, pt.params);
      for (int batch : batches) {
        std::vector<FramePair> views;
        for (int n = 0; n < batch; ++n) views.push_back(owned[n % kDistinctPairs].view());
        bool cpu_ok = false, vk_ok = false;
        const Timing c = measure(cpu_name, *cpu, views, pt.params, expected, min_time, cpu_ok);
        const Timing v = measure("vulkan", *vulkan, views, pt.params, expected, min_time, vk_ok);
        std::printf("%-26s %6d  %-8s %12.1f %12.1f %12.0f %10s\n", pt.label.c_str(), batch,
                    cpu_name.substr(0, 8).c_str(), c.wall_us, c.cpu_us, 1e6 / c.wall_us,
                    cpu_ok ? "1" : "WRONG");
        std::printf("%-26s %6d  %-8s %12.1f %12.1f %12.0f %10.3f%s\n", pt.label.c_str(), batch,
                    "vulkan", v.wall_us, v.cpu_us, 1e6 / v.wall_us, c.wall_us / v.wall_us,
                    vk_ok ? "" : " WRONG");
        std::fflush(stdout);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vulkan_bench: %s\n", e.what());
    return 2;
  }
  return 0;
}
