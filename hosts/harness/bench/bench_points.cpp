// What a bench measures: its default and quick sweeps, their threads, and the gate experiment's
// planted slowdown (bench.hpp).
#include <cstdlib>

#include "bench.hpp"
#include "errors.hpp"

namespace pxflow {

int planted_slowdown_from_environment() {
  const char* v = std::getenv("PXFLOW_BENCH_PLANTED_SLOWDOWN");
  if (!v || !*v) return 0;
  char* end = nullptr;
  const long p = std::strtol(v, &end, 10);
  if (*end != '\0' || p < 1 || p > 100)
    throw InputError("PXFLOW_BENCH_PLANTED_SLOWDOWN=" + std::string(v) +
                     ": expected a whole percent in 1..100 (the extra runs the gate's A/B "
                     "experiment plants; docs/harness.md)");
  return static_cast<int>(p);
}

std::vector<BenchPoint> default_bench_points(const Params& base, const std::string& name) {
  std::vector<BenchPoint> pts;
  for (int batch : {1, 16, 256, 4096}) pts.push_back({"batch", name, base, batch, 0});
  for (auto [w, h] : {std::pair{160, 120}, {320, 240}, {640, 480}}) {
    Params p = base;
    p.width = w, p.height = h;
    pts.push_back({"size", name, p, 16, 0});
  }
  for (int S : {2, 8}) {
    Params p = base;
    p.search_radius = S;
    pts.push_back({"radius", name, p, 256, 0});
  }
  pts.push_back({"threads", name, base, 256, 1});
  return pts;
}

std::vector<BenchPoint> quick_bench_points(const Params& base, const std::string& name) {
  std::vector<BenchPoint> pts = default_bench_points(base, name);
  std::erase_if(pts, [](const BenchPoint& p) {
    return p.batch > 256 || p.sweep == "radius" || p.sweep == "threads";
  });
  return pts;
}

void set_sweep_threads(std::vector<BenchPoint>& points, int threads) {
  for (BenchPoint& p : points)
    if (p.sweep != "threads") p.threads = threads;
}

}  // namespace pxflow
