// The CPU backends beyond the corpus (which cpu_path_check covers per ISA): the SWAR op counts,
// thread-count invariance of a batch, the ISA mask and table, and the registry rows. Every
// comparison with ref-original goes through the harness's exactness checker.
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstring>

#include "cpu_kernel.hpp"
#include "errors.hpp"
#include "exactness.hpp"
#include "grid.hpp"
#include "isa_mask.hpp"
#include "isa_table.hpp"
#include "registry.hpp"
#include "run_helpers.hpp"
#include "synthetic.hpp"
#include "window_guard.hpp"

using namespace pxflow;

namespace {

// Noise shifted by (+2, -1): every POI of px4flow-64 passes the feature test and is accepted.
OwnedPair all_pass_pair() {
  OwnedPair op;
  op.width = op.height = 64;
  Rng rng(42);
  op.prev.resize(64 * 64);
  for (auto& v : op.prev) v = static_cast<std::uint8_t>(rng.uniform(0, 255));
  shift_into(op.prev, op.next, 64, 64, 2, -1, 43);
  return op;
}

// Runs a batch on `backend` through check_exact; `counts` gets the backend's op counts.
Comparison exact(Backend& backend, const std::string& who, std::span<const FramePair> pairs,
                 const Params& p, OpCounts& counts) {
  std::vector<std::string> names;
  for (std::size_t n = 0; n < pairs.size(); ++n) names.push_back("pair" + std::to_string(n));
  return check_exact({who, "cpu_tests",
                      std::to_string(p.width) + "x" + std::to_string(p.height) +
                          " S=" + std::to_string(p.search_radius)},
                     pairs, names, p,
                     [&](std::span<const FramePair> batch, const Params& q,
                         std::span<PoiRecord> out) { backend.run(batch, q, out, counts); });
}

// The same with a fresh backend of row `name` on `threads` threads.
Comparison exact(const std::string& name, int threads, std::span<const FramePair> pairs,
                 const Params& p, OpCounts& counts) {
  const auto backend = find_backend(name).create(BackendOptions{threads, {}});
  return exact(*backend, name + " threads=" + std::to_string(threads), pairs, p, counts);
}

// ref-original's op counts for a batch.
OpCounts reference_counts(std::span<const FramePair> pairs, const Params& p) {
  OpCounts counts;
  for (const FramePair& pair : pairs) test::run_ref(RefVariant::kOriginal, pair, p, &counts);
  return counts;
}

// One pair through every ISA row that can run here, one thread each, against ref-original.
void check_every_available_isa(const FramePair& pair, const Params& p) {
  for (const std::string& isa : cpu::compiled_isas()) {
    if (!cpu::isa_unavailable(isa).empty()) continue;
    OpCounts c;
    const Comparison cmp = exact(isa, 1, {&pair, 1}, p, c);
    INFO(cmp.text());
    CHECK(cmp.ok());
  }
}

// A frame whose every row is followed by a page no one may read: row r's pixels end where page
// 2r + 1 of its mapping starts, and that page is PROT_NONE (stride two pages). A kernel load that
// reaches one byte past a row's pixels faults, masked lanes excepted.
class GuardedFrame {
 public:
  GuardedFrame(const std::vector<std::uint8_t>& pixels, int width, int height)
      : width_(width), height_(height), page_(sysconf(_SC_PAGESIZE)) {
    REQUIRE(width <= page_);
    bytes_ = static_cast<std::size_t>(2 * page_) * static_cast<std::size_t>(height);
    base_ = static_cast<std::uint8_t*>(
        mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0));
    REQUIRE(base_ != MAP_FAILED);
    for (int r = 0; r < height; ++r) {
      std::memcpy(row(r), pixels.data() + static_cast<std::ptrdiff_t>(r) * width, width);
      REQUIRE(mprotect(row(r) + width, page_, PROT_NONE) == 0);
    }
  }
  GuardedFrame(const GuardedFrame&) = delete;
  GuardedFrame& operator=(const GuardedFrame&) = delete;
  ~GuardedFrame() { munmap(base_, bytes_); }
  FrameView view() { return {width_, height_, 2 * page_, row(0)}; }

 private:
  std::uint8_t* row(int r) { return base_ + (2 * r + 1) * page_ - width_; }
  int width_, height_;
  std::ptrdiff_t page_;
  std::size_t bytes_ = 0;
  std::uint8_t* base_ = nullptr;
};

}  // namespace

// Kernels read a window in place wherever their row_bytes(S) stay inside the frame (avx512bw
// everywhere, with masked or plain 16-byte loads): with a fault after every row, a load past a
// row's pixels is a crash, not a silent read of the next row (which no record would show).
TEST_CASE("in-place windows read nothing past a frame row's pixels", "[cpu][window]") {
  for (int S = 1; S <= 8; ++S) {
    for (int width = 20 + 2 * S; width < 40 + 2 * S; ++width) {
      Params p = profile("px4flow-64");
      p.search_radius = S;
      p.width = width;
      p.height = 2 * S + 20;
      p.blocks = 3;
      validate(p);
      const OwnedPair op = random_pair(p.width, p.height, S, static_cast<std::uint64_t>(width));
      GuardedFrame prev(op.prev, p.width, p.height), next(op.next, p.width, p.height);
      const FramePair pair{prev.view(), next.view()};
      check_every_available_isa(pair, p);
    }
  }
}

TEST_CASE("swar counts 91,520 SAD ops per px4flow-64 frame where all 64 POIs pass", "[cpu][swar]") {
  const OwnedPair op = all_pass_pair();
  const FramePair pair = op.view();
  const Params p = profile("px4flow-64");
  OpCounts ref_counts;
  const auto ref = test::run_ref(RefVariant::kOriginal, pair, p, &ref_counts);
  REQUIRE(std::all_of(ref.begin(), ref.end(),
                      [](const PoiRecord& r) { return r.status == kAccepted; }));
  OpCounts counts;
  const Comparison cmp = exact("swar", 1, {&pair, 1}, p, counts);
  INFO(cmp.text());
  CHECK(cmp.ok());
  CHECK(counts.counted);
  CHECK(counts.sad_ops == 91520);
  CHECK(counts.interpolations == 64 * 768);  // the ref-original way of counting
  CHECK(ref_counts.sad_ops == counts.sad_ops);
}

TEST_CASE("a batch gives the same bytes whatever the thread count", "[cpu][threads]") {
  std::vector<OwnedPair> owned;
  for (std::uint64_t s = 1; s <= 13; ++s) owned.push_back(random_pair(64, 64, 4, s));
  std::vector<FramePair> pairs;
  for (const auto& op : owned) pairs.push_back(op.view());
  const Params p = profile("px4flow-64");
  const OpCounts ref_counts = reference_counts(pairs, p);
  for (const char* row : {"swar", "cpu"}) {
    for (int threads : {1, 2, 3, 0}) {
      OpCounts counts;
      const Comparison cmp = exact(row, threads, pairs, p, counts);
      INFO(cmp.text());
      CHECK(cmp.ok());
      if (std::string(row) == "swar") CHECK(counts.sad_ops == ref_counts.sad_ops);
    }
  }
}

TEST_CASE("small batches are split into bands of grid rows, same bytes", "[cpu][threads]") {
  Params p = profile("px4flow-64");
  p.width = 160;
  p.height = 120;
  p.search_radius = 7;
  p.blocks = 16;
  validate(p);
  const std::vector<OwnedPair> owned = {random_pair(160, 120, 7, 3), random_pair(160, 120, 7, 4)};
  for (std::size_t batch : {1u, 2u}) {
    std::vector<FramePair> pairs;
    for (std::size_t n = 0; n < batch; ++n) pairs.push_back(owned[n].view());
    const OpCounts ref_counts = reference_counts(pairs, p);
    for (int threads : {1, 2, 3, 7}) {
      INFO("batch " << batch);
      OpCounts counts;
      const Comparison swar = exact("swar", threads, pairs, p, counts);
      INFO(swar.text());
      CHECK(swar.ok());
      CHECK(counts.sad_ops == ref_counts.sad_ops);
      const Comparison cpu = exact("cpu", threads, pairs, p, counts);
      INFO(cpu.text());
      CHECK(cpu.ok());
    }
  }
}

TEST_CASE("a backend object runs many batches on its pool", "[cpu][threads]") {
  const Params p = profile("px4flow-head");
  auto backend = find_backend("cpu").create(BackendOptions{2, {}});
  for (std::uint64_t s = 1; s <= 5; ++s) {
    std::vector<OwnedPair> owned = {random_pair(64, 64, 8, s), random_pair(64, 64, 8, s + 100)};
    const FramePair pairs[2] = {owned[0].view(), owned[1].view()};
    OpCounts c;
    const Comparison cmp = exact(*backend, "cpu batch " + std::to_string(s), pairs, p, c);
    INFO(cmp.text());
    CHECK(cmp.ok());
  }
}

TEST_CASE("the ISA mask restricts the dispatcher and rejects unknown names", "[cpu][mask]") {
  CHECK_THROWS_AS(cpu::set_disabled_isas(cpu::compiled_isas().back() + ",bogus"), InputError);
  const std::string best = cpu::best_isa();
  REQUIRE_FALSE(best.empty());
  cpu::set_disabled_isas(best);
  CHECK(cpu::isa_unavailable(best) == "masked by --disable-isa");
  CHECK(cpu::best_isa() != best);
  CHECK_THROWS_AS(find_backend(best).create(BackendOptions{}), BackendError);
  cpu::set_disabled_isas(cpu::known_isas());  // every name, ", "-separated (spaces ignored)
  CHECK(cpu::best_isa().empty());
  CHECK_FALSE(find_backend("cpu").probe().empty());
  cpu::set_disabled_isas("");
  CHECK(cpu::best_isa() == best);
  CHECK(find_backend("cpu").probe().empty());
}

TEST_CASE("every compiled ISA and the dispatcher are registry rows", "[cpu][rows]") {
  for (const std::string& isa : cpu::compiled_isas()) {
    INFO(isa);
    const BackendRow& row = find_backend(isa);
    CHECK(row.name == isa);
    CHECK(row.needs == cpu::find_isa(isa)->needs);
    CHECK(row.probe() == cpu::isa_unavailable(isa));
  }
  CHECK(find_backend("cpu").probe().empty());
  CHECK(find_backend(cpu::compiled_isas().front()).probe().empty());  // the portable kernel
}

TEST_CASE("the ISA table: names, kernels and unknown names", "[cpu][table]") {
  REQUIRE(cpu::isa_table().size() >= 2);
  CHECK_FALSE(cpu::isa_table().front().cpu_has == nullptr);  // the portable row runs anywhere
  CHECK(cpu::isa_table().front().cpu_has());
  for (const cpu::IsaInfo& isa : cpu::isa_table()) {
    INFO(isa.name);
    CHECK(cpu::find_isa(isa.name) == &isa);
    CHECK((isa.cpu_has == nullptr) == !isa.compiled());
    // The accessor's kernel carries its row's name (the row, the file and the accessor agree).
    if (isa.compiled() && isa.cpu_has()) CHECK(std::string(isa.kernel().name) == isa.name);
  }
  CHECK(cpu::find_isa("avx-512") == nullptr);
  CHECK_THROWS_AS(cpu::isa_unavailable("avx-512"), InputError);
}

TEST_CASE("the widest search radius runs on every available ISA", "[cpu][radius]") {
  Params p = profile("px4flow-head");
  p.width = p.height = 80;
  p.search_radius = 31;
  p.blocks = 1;
  validate(p);
  const OwnedPair op = random_pair(80, 80, 31, 5);
  const FramePair pair = op.view();
  check_every_available_isa(pair, p);
}

// kernels/cpu/window_guard.hpp: what the guard around the right-edge window copy reports.
TEST_CASE("window guard: a byte changed past a row's pixels is reported, a short row_bytes refused",
          "[window-guard]") {
  CHECK_THROWS_WITH(cpu::WindowGuard(18, 17),
                    Catch::Contains("row_bytes = 17 for a window of 18 columns"));
  cpu::WindowGuard g(18, 32);  // avx2's row_bytes at S = 4: zeros from column 18 to 31
  for (int r = 0; r < g.side(); ++r) std::fill_n(g.row(r), g.side(), std::uint8_t{7});
  CHECK_NOTHROW(g.check(0));
  g.row(3)[18] = 1;  // one byte past the pixels: what a copy one byte too long writes
  CHECK_THROWS_WITH(g.check(40), Catch::Contains("byte 18 of row 3 changed") &&
                                     Catch::Contains("window at frame row 40"));
  g.row(3)[18] = 0;
  CHECK_NOTHROW(g.check(0));
#if !defined(__SANITIZE_ADDRESS__)  // under ASan the guard bytes are poisoned: ASan's to report
  g.row(17)[g.stride() - 1] ^= 1;
  CHECK_THROWS_WITH(g.check(0), Catch::Contains("of row 17 changed"));
  g.row(17)[g.stride() - 1] ^= 1;
  g.row(17)[g.stride()] ^= 1;  // the guard after the last row
  CHECK_THROWS_WITH(g.check(0), Catch::Contains("the guard after the last row"));
#endif
}

// poi_loop.cpp's check before the walk: a kernel whose row_bytes is short of the window's 2S+10
// columns is refused even where no POI needs the guarded copy (whose constructor checks too).
TEST_CASE("the POI walk refuses a kernel whose row_bytes is short of the window",
          "[window-guard]") {
  cpu::IsaKernel short_rows = cpu::swar_kernel();
  short_rows.row_bytes = [](int radius) { return 2 * radius + 9; };
  const Params p = profile("px4flow-64");  // S = 4: 17 bytes for a window of 18 columns
  const OwnedPair op = random_pair(p.width, p.height, p.search_radius, 7);
  const FramePair pair = op.view();
  std::vector<PoiRecord> out(poi_count(p));
  OpCounts counts;
  CHECK_THROWS_WITH(cpu::run_flow(short_rows, pair, p, out, counts),
                    Catch::Contains("row_bytes = 17 for a window of 18 columns"));
}

// A band of grid rows (one worker's share of a frame) writes its own rows' records only: the
// records after it are another worker's, or past the end of the batch's records. Every record is
// stale and "accepted" before the call, with hx and hy that no direction gives, so a pass over one
// record too many (e.g. the offsets written after a row's half-pixel steps) would change one.
TEST_CASE("a band of grid rows writes no record past its rows", "[cpu][threads]") {
  const Params p = profile("px4flow-64");
  const OwnedPair op = all_pass_pair();
  const FramePair pair = op.view();
  const int rows = grid_axis_triple(p.height, p).count;
  const auto per_row = poi_count(p) / static_cast<std::size_t>(rows);
  for (const cpu::IsaInfo& isa : cpu::isa_table()) {
    if (!isa.compiled() || !isa.cpu_has()) continue;
    INFO(isa.name);
    PoiRecord stale{};
    stale.status = kAccepted;
    stale.dir = kDirNone;
    stale.hx = stale.hy = 0x55;
    std::vector<PoiRecord> out(poi_count(p), stale);
    OpCounts counts;
    cpu::run_flow_rows(isa.kernel(), pair, p, 0, rows / 2, out, counts);
    for (std::size_t n = per_row * static_cast<std::size_t>(rows / 2); n < out.size(); ++n)
      CHECK(std::memcmp(&out[n], &stale, sizeof stale) == 0);
  }
}
