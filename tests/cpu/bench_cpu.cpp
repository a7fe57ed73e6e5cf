// bench_cpu: frames per second and TSC cycles per frame of every CPU row and ref-original, on
// one core and on all cores, at px4flow-64 and 640x480 (S=7, B=32), plus the SAD-instruction
// ceiling and each row's distance from it (bound_ratio). Google Benchmark; the rows are checked
// against ref-original on the benchmark's own frames with the harness's exactness checker before
// any timing (a mismatch prints its lines and the row is not timed).
//
//   build-cpu/tests/cpu/bench_cpu --benchmark_format=console   (or =json)
#include <benchmark/benchmark.h>
#include <x86intrin.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <map>
#include <thread>

#include "exactness.hpp"
#include "grid.hpp"
#include "isa_mask.hpp"
#include "psadbw_ceiling.hpp"
#include "registry.hpp"
#include "synthetic.hpp"

namespace pxflow::cpu_bench {
namespace {

double tsc_per_second() {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const std::uint64_t c0 = __rdtsc();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const std::uint64_t c1 = __rdtsc();
  const double s = std::chrono::duration<double>(clock::now() - t0).count();
  return static_cast<double>(c1 - c0) / s;
}

using cpu::Ceiling;

// The one-core ceiling (the bench's bound on one thread).
Ceiling measure_ceiling() {
  const Ceiling c = cpu::fastest_instruction();
  std::printf("ceiling  %s (the fastest of %s): %.1f bytes per TSC cycle\n", c.instruction.c_str(),
              cpu::ceiling_instructions().c_str(), c.bytes_per_cycle);
  return c;
}

struct Problem {
  std::string name;
  Params params;
  std::vector<OwnedPair> owned;
  std::vector<FramePair> pairs;
  std::vector<std::string> pair_names;
  ReferenceAnswer expected;    // ref-original's records and frame flows
  double bytes_per_frame = 0;  // SAD bytes compared per frame: the work the bound counts
};

// Random texture shifted by (+2, -1): every POI passes the feature test and is accepted.
Problem make_problem(std::string name, Params p, int frames) {
  validate(p);
  Problem pb{std::move(name), p, {}, {}, {}, {}, 0};
  for (int n = 0; n < frames; ++n) {
    OwnedPair op;
    op.width = p.width;
    op.height = p.height;
    Rng rng(1000 + n);
    op.prev.resize(static_cast<std::size_t>(p.width) * p.height);
    for (auto& v : op.prev) v = static_cast<std::uint8_t>(rng.uniform(0, 255));
    shift_into(op.prev, op.next, p.width, p.height, 2, -1, 2000 + n);
    pb.owned.push_back(std::move(op));
  }
  for (const auto& op : pb.owned) pb.pairs.push_back(op.view());
  for (int n = 0; n < frames; ++n) pb.pair_names.push_back("seed" + std::to_string(1000 + n));
  pb.expected = reference_answer(pb.pairs, p);
  const double side = 2 * p.search_radius + 1;
  for (const PoiRecord& r : pb.expected.records)
    pb.bytes_per_frame +=
        (r.status >= kRejected ? side * side * 64 : 0) + (r.status == kAccepted ? 8 * 64 : 0);
  pb.bytes_per_frame /= static_cast<double>(pb.pairs.size());
  return pb;
}

struct Context {
  double tsc_hz = 0;
  Ceiling ceiling;
  std::map<std::string, double> ref_cycles;  // problem -> ref-original cycles per frame
};

// One timed row: every iteration runs the whole batch; TSC cycles per frame are the wall
// cycles of the fastest batch over its frames, so on all cores they measure throughput.
void run_row(benchmark::State& state, const std::string& row, int threads, const Problem& pb,
             Context& ctx) {
  if (const std::string why = find_backend(row).probe(); !why.empty()) {
    state.SkipWithError(("skipped: " + why).c_str());
    return;
  }
  auto backend = find_backend(row).create(BackendOptions{threads, {}});
  std::vector<PoiRecord> out = sentinel_records(pb.expected.records.size());
  OpCounts counts;
  backend->run(pb.pairs, pb.params, out, counts);
  const Comparison cmp = compare_with_reference({row, pb.name, "bench_cpu"}, pb.pair_names,
                                                pb.params, pb.expected, out, 5);
  if (!cmp.ok()) {
    std::fputs(cmp.text().c_str(), stderr);
    state.SkipWithError("records differ from ref-original: not timed");
    return;
  }
  // The fastest batch of the run: on a shared machine the mean also measures other processes.
  std::uint64_t fastest = UINT64_MAX, frames = 0;
  for (auto _ : state) {
    const std::uint64_t c0 = __rdtsc();
    backend->run(pb.pairs, pb.params, out, counts);
    fastest = std::min<std::uint64_t>(fastest, __rdtsc() - c0);
    frames += pb.pairs.size();
  }
  const double per_frame = static_cast<double>(fastest) / static_cast<double>(pb.pairs.size());
  if (row == "ref-original" && threads == 1) ctx.ref_cycles[pb.name] = per_frame;
  const double bound = pb.bytes_per_frame / ctx.ceiling.bytes_per_cycle;
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
  state.counters["cycles_per_frame"] = per_frame;
  state.counters["peak_frames_per_s"] = ctx.tsc_hz / per_frame;
  state.counters["bound_ratio"] = per_frame / bound;
  if (ctx.ref_cycles.count(pb.name))
    state.counters["speedup_vs_ref"] = ctx.ref_cycles[pb.name] / per_frame;
}

}  // namespace
}  // namespace pxflow::cpu_bench

int main(int argc, char** argv) {
  using namespace pxflow;
  using namespace pxflow::cpu_bench;
  static Context ctx;
  ctx.tsc_hz = tsc_per_second();
  std::printf("TSC      %.3f GHz (calibrated against steady_clock over 200 ms)\n",
              ctx.tsc_hz / 1e9);
  ctx.ceiling = measure_ceiling();
  Params big = profile("px4flow-64");
  big.width = 640;
  big.height = 480;
  big.search_radius = 7;
  big.blocks = 32;
  static std::vector<Problem> problems;
  problems.push_back(make_problem("px4flow-64", profile("px4flow-64"), 64));
  problems.push_back(make_problem("640x480_S7_B32", big, 8));
  for (const Problem& pb : problems)
    std::printf(
        "problem  %s: %zu POIs, %.0f SAD bytes per frame, bound %.0f TSC cycles per frame\n",
        pb.name.c_str(), poi_count(pb.params), pb.bytes_per_frame,
        pb.bytes_per_frame / ctx.ceiling.bytes_per_cycle);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::string> rows = {"ref-original"};
  for (const std::string& isa : cpu::compiled_isas()) rows.push_back(isa);
  for (const Problem& pb : problems)
    for (const std::string& row : rows)
      for (int threads : {1, static_cast<int>(cores)}) {
        if (row == "ref-original" && threads > 1) continue;  // the reference is single-threaded
        const std::string name = pb.name + "/" + row + "/threads:" + std::to_string(threads);
        benchmark::RegisterBenchmark(
            name.c_str(),
            [&pb, row, threads](benchmark::State& s) { run_row(s, row, threads, pb, ctx); })
            ->UseRealTime()
            ->Unit(benchmark::kMicrosecond);
      }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
