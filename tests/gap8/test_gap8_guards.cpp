// The GAP8 model's guard zones around its result areas (hosts/gap8/gap8_flow_runner.cpp) and the
// limits `pxflow check` finds from each variant's unsupported()
// (hosts/harness/check/check_limits.hpp).
#include <algorithm>
#include <catch2/catch.hpp>

#include "check_limits.hpp"
#include "errors.hpp"
#include "gap8_backend.hpp"
#include "gap8_flow_runner.hpp"
#include "gap8_variants.hpp"
#include "grid.hpp"
#include "synthetic.hpp"

namespace pxflow::test {

using Catch::Matchers::Contains;

TEST_CASE("gap8: a store planted past the L2 or L1 records is a write past the output", "[gap8]") {
  const Params p = profile("px4flow-64");
  const OwnedPair pair = random_pair(64, 64, 4, 5);
  const FramePair view = pair.view();
  std::vector<PoiRecord> out(poi_count(p));
  const gap8_host::FlowRunner runner(Gap8Variant::kLocal);
  gap8_host::RunOptions clean;
  CHECK_NOTHROW(runner.run({&view, 1}, p, out, clean));
  gap8_host::RunOptions l2 = clean;
  l2.plant_past_l2_records = 1;
  CHECK_THROWS_WITH(runner.run({&view, 1}, p, out, l2),
                    "gap8 model (L2 records): wrote past its output (1 bytes after record 63)");
  gap8_host::RunOptions l1 = clean;
  l1.plant_past_l1_records = 5;
  CHECK_THROWS_WITH(runner.run({&view, 1}, p, out, l1),
                    "gap8 model (L1 records): wrote past its output (5 bytes after record 63)");
}

TEST_CASE("gap8: the check's limit cases are each variant's exact edges", "[gap8]") {
  for (const Gap8VariantInfo& v : gap8_variants()) {
    const std::string name = std::string("gap8-") + v.name;
    INFO(name);
    const Gap8Backend backend(v.id, {});
    const LimitRow row{name, [&](const Params& p) { return backend.unsupported(p); }};
    bool square = false;
    int sweep_top = 0, largest_radius = 0;
    for (const LimitProbe& probe : limit_probes({&row, 1})) {
      if (probe.rows.empty()) continue;  // SPEC's corners, not this row's edges
      INFO(probe.what());
      CHECK(backend.unsupported(probe.params).empty());
      if (probe.kind == "radius-sweep") {  // every radius it accepts, each once
        sweep_top = std::max(sweep_top, probe.params.search_radius);
        continue;
      }
      if (probe.kind == "largest-radius") largest_radius = probe.params.search_radius;
      // One step further along the searched dimension is refused (or outside SPEC's ranges).
      Params next = probe.params;
      const std::string kind = probe.kind;
      if (kind.starts_with("largest-square")) ++next.width, ++next.height, square = true;
      if (kind.starts_with("widest")) ++next.width;
      if (kind.starts_with("tallest")) ++next.height;
      if (kind.starts_with("largest-radius")) ++next.search_radius;
      if (kind.starts_with("largest-blocks")) ++next.blocks;
      if (next.search_radius <= kMaxSearchRadius && next.blocks <= kMaxBlocks)
        CHECK_THAT(backend.unsupported(next), Contains("does not fit L1"));
    }
    CHECK(square);  // every variant has an L1 limit below the frame size limit
    // The sweep reaches the largest radius the variant accepts (or SPEC's, where it has none).
    CHECK(sweep_top == (largest_radius > 0 ? largest_radius : kMaxSearchRadius));
  }
}

}  // namespace pxflow::test
