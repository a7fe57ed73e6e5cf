// The broken family's rows: ref-original, each with one deliberate fault, so that the check's
// isolation is tested against what real broken kernels do (docs/harness.md, "Isolation").
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <thread>

#include "backend.hpp"
#include "grid.hpp"
#include "kernel.hpp"

namespace pxflow {
namespace {

enum class Fault { kCrash, kAbort, kHang, kOverrun, kUnderrun, kOverread, kMiscount };

class BrokenBackend final : public Backend {
 public:
  explicit BrokenBackend(Fault f) : fault_(f) {}
  void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
           OpCounts& counts) override {
    // Each fault fires on the fixed corpus's 64x64 cases (0 to 7; the crash on those pairs whose
    // first pixel is odd, alone as in their case: the check finds the pair by running them one
    // by one); the later cases show the check going on with the row. The hang comes once, in the
    // ninth run of a worker at 320x240 (case 8, random 320x240: the row's speed is measured by
    // then). The fresh worker that takes over does reach a ninth run, in the limit cases, none
    // of them 320x240: each hang there would be another --case-timeout of waiting (7 of them,
    // 35 s of the test's 44, before the frame size was part of the rule).
    const bool faulty = p.width == 64;
    if (fault_ == Fault::kHang && ++runs_ == 9 && p.width == 320)
      for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
    const std::size_t per = poi_count(p);
    for (std::size_t n = 0; n < pairs.size(); ++n) {
      if (faulty && fault_ == Fault::kCrash && pairs[n].prev.data[0] % 2 == 1) std::raise(SIGSEGV);
      if (faulty && fault_ == Fault::kAbort) std::abort();
      if (faulty && fault_ == Fault::kOverread) {  // one byte past the end of the next frame
        const FrameView& f = pairs[n].next;
        volatile std::uint8_t past = f.data[(f.height - 1) * f.stride + f.width];
        (void)past;
      }
      reference_flow(RefVariant::kOriginal, pairs[n], p, out.subspan(n * per, per), counts);
    }
    // One record past the output's end, or before its start (the records around it are not the
    // backend's: the guards).
    if (faulty && fault_ == Fault::kOverrun) out.data()[out.size()] = out.back();
    if (faulty && fault_ == Fault::kUnderrun) out.data()[-1] = out.front();
    if (faulty && fault_ == Fault::kMiscount) counts.sad_ops += 1;
  }

 private:
  Fault fault_;
  int runs_ = 0;
};

BackendRow row(const char* name, Fault f) {
  BackendRow r{name, "nothing (test family)", [] { return std::string(); },
               [f](const BackendOptions&) { return std::make_unique<BrokenBackend>(f); }};
  r.counts_like = RefVariant::kOriginal;  // ref-original's kernel counts its work
  return r;
}

}  // namespace

BackendFamily broken_family() {
  return {"broken",
          {row("broken-crash", Fault::kCrash), row("broken-abort", Fault::kAbort),
           row("broken-hang", Fault::kHang), row("broken-overrun", Fault::kOverrun),
           row("broken-underrun", Fault::kUnderrun), row("broken-overread", Fault::kOverread),
           row("broken-miscount", Fault::kMiscount)},
          {},
          {}};
}

}  // namespace pxflow
