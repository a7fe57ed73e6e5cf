// The CPU backends beyond bit-exactness (which cpu_path_check covers per ISA): the SWAR op
// counts, thread-count invariance of a batch, the ISA mask, and the registry rows.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstring>

#include "cpu_corpus.hpp"
#include "errors.hpp"
#include "grid.hpp"
#include "isa_mask.hpp"
#include "kernel.hpp"
#include "registry.hpp"
#include "synthetic.hpp"

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

std::vector<PoiRecord> run_row(const std::string& name, int threads,
                               std::span<const FramePair> pairs, const Params& p,
                               OpCounts& counts) {
  std::vector<PoiRecord> out(pairs.size() * poi_count(p));
  std::memset(out.data(), 0xA5, out.size() * sizeof(PoiRecord));
  find_backend(name).create(BackendOptions{threads, {}})->run(pairs, p, out, counts);
  return out;
}

bool same_bytes(const std::vector<PoiRecord>& a, const std::vector<PoiRecord>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(PoiRecord)) == 0;
}

}  // namespace

TEST_CASE("swar counts 91,520 SAD ops per px4flow-64 frame where all 64 POIs pass", "[cpu][swar]") {
  const OwnedPair op = all_pass_pair();
  const FramePair pair = op.view();
  const Params p = profile("px4flow-64");
  OpCounts counts;
  const auto recs = run_row("swar", 1, {&pair, 1}, p, counts);
  REQUIRE(std::all_of(recs.begin(), recs.end(),
                      [](const PoiRecord& r) { return r.status == kAccepted; }));
  CHECK(counts.counted);
  CHECK(counts.sad_ops == 91520);
  CHECK(counts.interpolations == 64 * 768);  // the ref-original way of counting
  OpCounts ref_counts;
  std::vector<PoiRecord> ref(recs.size());
  reference_flow(RefVariant::kOriginal, pair, p, ref, ref_counts);
  CHECK(same_bytes(ref, recs));
  CHECK(ref_counts.sad_ops == counts.sad_ops);
}

TEST_CASE("a batch gives the same bytes whatever the thread count", "[cpu][threads]") {
  std::vector<OwnedPair> owned;
  for (std::uint64_t s = 1; s <= 13; ++s) owned.push_back(random_pair(64, 64, 4, s));
  std::vector<FramePair> pairs;
  for (const auto& op : owned) pairs.push_back(op.view());
  const Params p = profile("px4flow-64");
  OpCounts ref_counts;
  std::vector<PoiRecord> ref(pairs.size() * poi_count(p));
  for (std::size_t n = 0; n < pairs.size(); ++n)
    reference_flow(RefVariant::kOriginal, pairs[n], p,
                   std::span(ref).subspan(n * poi_count(p), poi_count(p)), ref_counts);
  for (const char* row : {"swar", "cpu"}) {
    for (int threads : {1, 2, 3, 0}) {
      INFO(row << " with " << threads << " threads");
      OpCounts counts;
      CHECK(same_bytes(ref, run_row(row, threads, pairs, p, counts)));
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
    std::vector<PoiRecord> ref(batch * poi_count(p));
    OpCounts ref_counts;
    for (std::size_t n = 0; n < batch; ++n)
      reference_flow(RefVariant::kOriginal, pairs[n], p,
                     std::span(ref).subspan(n * poi_count(p), poi_count(p)), ref_counts);
    for (int threads : {1, 2, 3, 7}) {
      INFO("batch " << batch << ", " << threads << " threads");
      OpCounts counts;
      CHECK(same_bytes(ref, run_row("swar", threads, pairs, p, counts)));
      CHECK(counts.sad_ops == ref_counts.sad_ops);
      CHECK(same_bytes(ref, run_row("cpu", threads, pairs, p, counts)));
    }
  }
}

TEST_CASE("a backend object runs many batches on its pool", "[cpu][threads]") {
  const Params p = profile("px4flow-head");
  auto backend = find_backend("cpu").create(BackendOptions{2, {}});
  for (std::uint64_t s = 1; s <= 5; ++s) {
    std::vector<OwnedPair> owned = {random_pair(64, 64, 8, s), random_pair(64, 64, 8, s + 100)};
    const FramePair pairs[2] = {owned[0].view(), owned[1].view()};
    std::vector<PoiRecord> got(2 * poi_count(p)), ref(2 * poi_count(p));
    OpCounts c;
    backend->run(pairs, p, got, c);
    for (int n = 0; n < 2; ++n)
      reference_flow(RefVariant::kOriginal, pairs[n], p,
                     std::span(ref).subspan(n * poi_count(p), poi_count(p)), c);
    CHECK(same_bytes(ref, got));
  }
}

TEST_CASE("the ISA mask restricts the dispatcher and rejects unknown names", "[cpu][mask]") {
  CHECK_THROWS_AS(cpu::set_disabled_isas("avx2,bogus"), InputError);
  const std::string best = cpu::best_isa();
  REQUIRE_FALSE(best.empty());
  cpu::set_disabled_isas(best);
  CHECK(cpu::isa_unavailable(best) == "masked by --disable-isa");
  CHECK(cpu::best_isa() != best);
  CHECK_THROWS_AS(find_backend(best).create(BackendOptions{}), BackendError);
  cpu::set_disabled_isas("swar, sse2,sse41,avx2,avx512bw,neon");
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
    CHECK(row.probe() == cpu::isa_unavailable(isa));
  }
  CHECK(find_backend("cpu").probe().empty());
  CHECK(find_backend("swar").probe().empty());
}

TEST_CASE("the widest search radius runs on every available ISA", "[cpu][radius]") {
  Params p = profile("px4flow-head");
  p.width = p.height = 80;
  p.search_radius = 31;
  p.blocks = 1;
  validate(p);
  const OwnedPair op = random_pair(80, 80, 31, 5);
  const FramePair pair = op.view();
  std::vector<PoiRecord> ref(poi_count(p));
  OpCounts c;
  reference_flow(RefVariant::kOriginal, pair, p, ref, c);
  for (const std::string& isa : cpu::compiled_isas()) {
    if (!cpu::isa_unavailable(isa).empty()) continue;
    INFO(isa);
    CHECK(same_bytes(ref, run_row(isa, 1, {&pair, 1}, p, c)));
  }
}
