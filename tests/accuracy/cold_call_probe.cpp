// pxflow_accuracy_probe: where pxflow's time per frame goes in `pxflow accuracy` (docs/accuracy.md,
// "What limits pxflow against LK"). A tool, not a test: it checks nothing and prints timings.
//
// It times PxflowEstimator::estimate, the call `pxflow accuracy` times, on the same kinds of
// pairs, one thread, in the accuracy's order (pxflow, LK, DIS on each pair in turn), with one
// untimed preparation before pxflow's call that makes one part of the state warm:
//   as accuracy    none: the pair and everything else as LK and DIS of the previous pair left them
//   pages touched  one byte of every 4 KB page of the pair read (its page walks done)
//   pair read      every 64-byte line of the pair read (the pair in L2, its pages walked)
//   LK first       LK on this pair (the accuracy's order reversed: the preparation's median is
//                  LK's time on the cold pair, against the LK column's, LK after pxflow)
//   other pair     pxflow on the next pair (code, branch history, vector units warm; this pair
//   cold) same pair      pxflow on this pair (everything warm) same, idle     pxflow on this pair,
//   then 1 ms of scalar work (a spin on the clock) idle, wide     the same, then 20 us of 512-bit
//   adds (x86 with AVX-512 only; else as idle):
//                  the difference to "same, idle" is what the wide units' power-up costs
// The preparations alternate pass by pass; each column is the median over its calls, with the
// median time of the preparation itself (for "pages touched": the page walks' own cost).
//
//   pxflow_accuracy_probe [--backend NAME] [--only TEXT] [--passes N]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "accuracy_run.hpp"
#include "check_corpus.hpp"
#include "estimators.hpp"
#include "opencv_module.hpp"
#include "params.hpp"
#include "sample_data.hpp"
#include "truth_pairs.hpp"

namespace pxflow::accuracy {
namespace {

using Clock = std::chrono::steady_clock;

struct ProbeOptions {
  std::string backend = "cpu";
  std::string only;  // sets whose name contains it; empty: all
  int passes = 3;    // per preparation; the video sets take 2x as many (6 pairs each)
};

struct PairSet {
  std::string name;
  Params p;
  std::vector<std::pair<Frame, Frame>> pairs;
};

enum class Prep {
  kNone,
  kPagesTouched,
  kPairRead,
  kLkFirst,
  kOtherPair,
  kSamePair,
  kIdle,
  kIdleWide
};
constexpr Prep kPreps[] = {Prep::kNone,      Prep::kPagesTouched, Prep::kPairRead, Prep::kLkFirst,
                           Prep::kOtherPair, Prep::kSamePair,     Prep::kIdle,     Prep::kIdleWide};
constexpr const char* kPrepNames[] = {"as accuracy", "pages touched", "pair read",  "LK first",
                                      "other pair",  "same pair",     "same, idle", "idle, wide"};
constexpr std::size_t kPrepCount = std::size(kPreps);

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

double micros(Clock::duration d) { return std::chrono::duration<double, std::micro>(d).count(); }

// The sets of `pxflow accuracy` at --seed 1 (its seeds and counts; the videos' 6 pairs each).
std::vector<PairSet> pair_sets() {
  const auto images = load_source_images(kSampleDataDir);
  std::vector<PairSet> sets;
  auto synthetic = [&](const std::string& name, const Params& p, Geometry g, int n, int seed) {
    PairSet s{name, p, {}};
    for (auto& t : make_truth_pairs(images, g, n, seed)) s.pairs.emplace_back(t.prev, t.next);
    sets.push_back(std::move(s));
  };
  synthetic("64x64 px4flow-64", profile(kDefaultProfile), Geometry::kCamera64, 200, 100000);
  synthetic("320x240 S=7 B=16", check_settings()[2].second, Geometry::kWindow320, 50, 150000);
  for (const char* video : kVideos) {
    const auto vp = video_pairs(std::string(kSampleDataDir) + "/" + video, 6);
    PairSet s{video, video_setting(vp.front().prev.width, vp.front().prev.height), {}};
    for (const auto& v : vp) s.pairs.emplace_back(v.prev, v.next);
    sets.push_back(std::move(s));
  }
  return sets;
}

// Reads one byte every `step` bytes of each frame's pixels; returns their sum (kept by the caller).
unsigned read_frames(const Frame& a, const Frame& b, std::ptrdiff_t step) {
  unsigned sum = 0;
  for (const Frame* f : {&a, &b}) {
    const std::uint8_t* end = f->view().row(f->height - 1) + f->width;
    for (const std::uint8_t* q = f->view().row(0); q < end; q += step) sum += *q;
  }
  return sum;
}

struct Times {
  std::vector<double> px[kPrepCount], prep[kPrepCount], lk;
};

void spin_scalar(std::chrono::microseconds d) {
  const auto until = Clock::now() + d;
  volatile unsigned long n = 0;
  while (Clock::now() < until) n = n + 1;
}

#if defined(__x86_64__)
[[gnu::target("avx512f")]] void spin_wide_x86(std::chrono::microseconds d) {
  const auto until = Clock::now() + d;
  __m512i a = _mm512_set1_epi32(1), b = a;
  while (Clock::now() < until)
    for (int i = 0; i < 64; ++i) a = _mm512_add_epi32(a, b), b = _mm512_add_epi32(b, a);
  int lanes[16];
  _mm512_storeu_si512(lanes, a);
  volatile int keep = lanes[0];
  (void)keep;
}
#endif

// 512-bit work for `d` where this CPU has AVX-512; nothing elsewhere.
void spin_wide(std::chrono::microseconds d) {
#if defined(__x86_64__)
  if (__builtin_cpu_supports("avx512f")) spin_wide_x86(d);
#else
  (void)d;
#endif
}

void prepare(Prep prep, const std::pair<Frame, Frame>& pair, const std::pair<Frame, Frame>& other,
             PxflowEstimator& px, LucasKanadeEstimator& lk) {
  const auto& [a, b] = pair;
  volatile unsigned keep = 0;
  if (prep == Prep::kPagesTouched) keep = read_frames(a, b, 4096);
  if (prep == Prep::kPairRead) keep = read_frames(a, b, 64);
  if (prep == Prep::kLkFirst) lk.estimate(a, b);
  if (prep == Prep::kOtherPair) px.estimate(other.first, other.second);
  if (prep == Prep::kSamePair || prep == Prep::kIdle || prep == Prep::kIdleWide) px.estimate(a, b);
  if (prep == Prep::kIdle || prep == Prep::kIdleWide) spin_scalar(std::chrono::milliseconds(1));
  if (prep == Prep::kIdleWide) spin_wide(std::chrono::microseconds(20));
  (void)keep;
}

void one_pass(PairSet& s, Prep prep, PxflowEstimator& px, LucasKanadeEstimator& lk,
              DisEstimator& dis, Times& t) {
  const auto m = static_cast<std::size_t>(prep);
  for (std::size_t i = 0; i < s.pairs.size(); ++i) {
    const auto& [a, b] = s.pairs[i];
    const auto t0 = Clock::now();
    prepare(prep, s.pairs[i], s.pairs[(i + 1) % s.pairs.size()], px, lk);
    const auto t1 = Clock::now();
    px.estimate(a, b);
    const auto t2 = Clock::now();
    lk.estimate(a, b);
    const auto t3 = Clock::now();
    dis.estimate(a, b);
    t.prep[m].push_back(micros(t1 - t0));
    t.px[m].push_back(micros(t2 - t1));
    if (prep == Prep::kNone) t.lk.push_back(micros(t3 - t2));
  }
}

void probe_set(PairSet& s, const ProbeOptions& o) {
  BackendOptions bo;
  bo.threads = 1;
  PxflowEstimator px(o.backend, bo, s.p);
  LucasKanadeEstimator lk(px.poi_centres(), s.p);
  DisEstimator dis;
  Times t;
  const int passes = s.pairs.size() < 20 ? 2 * o.passes : o.passes;
  for (int pass = 0; pass < passes; ++pass)
    for (Prep prep : kPreps) one_pass(s, prep, px, lk, dis, t);
  const double lk_us = median(t.lk);
  std::printf("| %s | %.0f | %.2f |", s.name.c_str(), lk_us, lk_us / 100);
  for (std::size_t m = 0; m < kPrepCount; ++m)
    std::printf(" %.2f (%.2f) |", median(t.px[m]), median(t.prep[m]));
  std::printf("\n");
  std::fflush(stdout);
}

ProbeOptions parse(int argc, char** argv) {
  ProbeOptions o;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--backend")) o.backend = argv[i + 1];
    if (!std::strcmp(argv[i], "--only")) o.only = argv[i + 1];
    if (!std::strcmp(argv[i], "--passes")) o.passes = std::max(1, std::atoi(argv[i + 1]));
  }
  return o;
}

}  // namespace
}  // namespace pxflow::accuracy

int main(int argc, char** argv) {
  using namespace pxflow::accuracy;
  const ProbeOptions o = parse(argc, argv);
  pxflow::opencv_api().set_threads(1);
  std::printf("pxflow (%s) per frame, median us (preparation's median us); LK median us\n\n",
              o.backend.c_str());
  std::printf("| pairs | LK | LK / 100 |");
  for (const char* name : kPrepNames) std::printf(" %s |", name);
  std::printf("\n|---|---|---|");
  for (std::size_t m = 0; m < kPrepCount; ++m) std::printf("---|");
  std::printf("\n");
  for (PairSet& s : pair_sets())
    if (s.name.find(o.only) != std::string::npos) probe_set(s, o);
}
