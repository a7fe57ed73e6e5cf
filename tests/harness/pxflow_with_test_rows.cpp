// pxflow with extra registry rows that exist only in this test program, to prove that the checker
// catches what it must: a backend that flips one bit, one that leaves a record unwritten, one
// that miscounts its work, one with a planted half-pixel bug (for the reproducer), one that
// cannot run, one with a documented size limit, one that crashes and one that hangs.
#include <chrono>
#include <csignal>
#include <cstring>
#include <thread>

#include "grid.hpp"
#include "kernel.hpp"
#include "poi_steps.hpp"
#include "pxflow_app.hpp"
#include "registry.hpp"

namespace {

using namespace pxflow;

// Runs ref-original, then damages the output the way `Fault` says; or crashes, or never returns.
enum class Fault { kFlipBit, kSkipRecord, kMiscount, kSwapHalfSteps, kNone, kCrash, kHang };

// The planted bug of a CPU-like kernel: for a match to the right (dx > 0) it takes the left and
// right half steps (directions 0 and 4) for each other, then votes as SPEC §3 says.
void swap_half_steps(PoiRecord& r) {
  if (r.status != kAccepted || r.dx <= 0) return;
  std::uint32_t sub[8];
  for (int k = 0; k < 8; ++k) sub[k] = r.sub[k];
  std::swap(sub[0], sub[4]);
  ref::select_half_pixel(r, ref::Match{r.dx, r.dy, r.sad}, sub);
}

class Damaged final : public Backend {
 public:
  Damaged(Fault f, int max_side) : fault_(f), max_side_(max_side) {}
  void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
           OpCounts& c) override {
    if (fault_ == Fault::kCrash) std::raise(SIGSEGV);
    if (fault_ == Fault::kHang)
      for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
    const std::size_t per = poi_count(p);
    for (std::size_t n = 0; n < pairs.size(); ++n) {
      auto recs = out.subspan(n * per, per);
      std::vector<PoiRecord> tmp(per);
      reference_flow(RefVariant::kOriginal, pairs[n], p, tmp, c);
      for (std::size_t i = 0; i < per; ++i) {
        if (fault_ == Fault::kSkipRecord && i == 5) continue;  // leaves the sentinel
        recs[i] = tmp[i];
      }
      if (fault_ == Fault::kFlipBit && per > 3) recs[3].sub[2] ^= 1;  // one bit of one record
      if (fault_ == Fault::kSwapHalfSteps)
        for (PoiRecord& r : recs) swap_half_steps(r);
    }
    if (fault_ == Fault::kMiscount) c.sad_ops += 512;  // records right, the count of a batch not
  }
  std::string unsupported(const Params& p) const override {
    if (p.width > max_side_ || p.height > max_side_)
      return "frames larger than " + std::to_string(max_side_) + " pixels";
    return {};
  }

 private:
  Fault fault_;
  int max_side_;
};

BackendRow row(const char* name, Fault f, int max_side, std::string probe_reason = {}) {
  BackendRow r{
      name, "test only", [probe_reason] { return probe_reason; },
      [f, max_side](const BackendOptions&) { return std::make_unique<Damaged>(f, max_side); }};
  r.counts_like = RefVariant::kOriginal;  // ref-original's kernel counts its work
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  add_backend_row(row("test-bitflip", Fault::kFlipBit, 1 << 20));
  add_backend_row(row("test-unwritten", Fault::kSkipRecord, 1 << 20));
  add_backend_row(row("test-miscount", Fault::kMiscount, 1 << 20));
  add_backend_row(row("test-half-step-swap", Fault::kSwapHalfSteps, 1 << 20));
  add_backend_row(row("test-unavailable", Fault::kNone, 1 << 20, "no such device here (test row)"));
  add_backend_row(row("test-small-only", Fault::kNone, 64));
  add_backend_row(row("test-crash", Fault::kCrash, 1 << 20));
  add_backend_row(row("test-hang", Fault::kHang, 1 << 20));
  // A row whose hardware this machine lacks (as an ISA row on an older CPU).
  BackendRow lacking =
      row("test-no-hardware", Fault::kNone, 1 << 20, "this CPU lacks it (test row)");
  lacking.host_lacks = [] { return true; };
  add_backend_row(lacking);
  return run_pxflow(argc, argv);
}
