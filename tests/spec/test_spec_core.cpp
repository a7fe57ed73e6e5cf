// The spec core's code (grid, parameter check, estimate: spec/include/pxflow_spec) against the
// reference's readable C++ on many inputs: the two must agree everywhere, so that a change to
// either copy fails here before any backend runs. The constants are static_asserted at build
// time (reference/spec_core.cpp).
#include <bit>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "errors.hpp"
#include "estimate.hpp"
#include "grid.hpp"
#include "param_fields.hpp"
#include "params.hpp"
#include "pxflow_spec/spec.h"
#include "spec_params.hpp"

using namespace pxflow;

namespace {

bool core_accepts(const Params& p) {
  const pxflow_param_block q = spec_params(p);
  return pxflow_check_params(&q) == PXFLOW_PARAMS_OK;
}

bool reference_accepts(const Params& p) {
  try {
    validate(p);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

TEST_CASE("spec core: the grid axis is the reference's for every S, B and side", "[spec]") {
  Params p;
  int compared = 0;
  for (int s = kMinSearchRadius; s <= kMaxSearchRadius; ++s)
    for (int b = kMinBlocks; b <= kMaxBlocks; b += (b < 20 ? 1 : 7))
      for (int side = 1; side <= 300; ++side) {
        p.search_radius = s, p.blocks = b;
        const GridAxis want = grid_axis_triple(side, p);
        const pxflow_grid_axis got =
            pxflow_grid_axis_of(static_cast<std::uint32_t>(side), static_cast<std::uint32_t>(s),
                                static_cast<std::uint32_t>(b));
        if (static_cast<int>(got.count) != want.count ||
            (want.count > 0 && (static_cast<int>(got.first) != want.first ||
                                static_cast<int>(got.step) != want.step))) {
          FAIL("S=" << s << " B=" << b << " side=" << side << ": core " << got.first << "+"
                    << got.step << " x" << got.count << ", reference " << want.first << "+"
                    << want.step << " x" << want.count);
        }
        ++compared;
      }
  CHECK(compared > 100000);
}

TEST_CASE("spec core: the parameter check accepts exactly what validate() accepts", "[spec]") {
  // Each field at the edges of its range, the others at the default profile's values.
  const std::vector<int> edges = {-1, 0,  1,   2,   7,   8,     9,     22,    23,    30,   31,
                                  32, 64, 254, 255, 256, 65535, 65536, 16383, 16384, 16385};
  int Params::*fields[] = {&Params::width,         &Params::height,   &Params::search_radius,
                           &Params::tile,          &Params::blocks,   &Params::feature_threshold,
                           &Params::sad_threshold, &Params::min_count};
  int compared = 0;
  for (int Params::*field : fields)
    for (int v : edges) {
      Params p;
      p.*field = v;
      INFO("field value " << v);
      CHECK(core_accepts(p) == reference_accepts(p));
      ++compared;
    }
  // Both sides at once: the pixel limit and the smallest frame of each radius.
  for (int s : {1, 4, 31})
    for (int side : {1, 2 * (s + 1) + 8, 2 * (s + 1) + 9, 8192, 8193, 16384}) {
      Params p;
      p.search_radius = s, p.width = side, p.height = side;
      INFO("S " << s << ", side " << side);
      CHECK(core_accepts(p) == reference_accepts(p));
      ++compared;
    }
  CHECK(compared == 8 * 21 + 18);
}

TEST_CASE("spec core: the estimate's bits are the reference's on random record sets", "[spec]") {
  std::mt19937 rng(24);
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  for (int round = 0; round < 2000; ++round) {
    Params p;
    p.search_radius = pick(1, kMaxSearchRadius);
    p.blocks = pick(1, 12);
    p.hist_filter = pick(0, 1) != 0;
    p.min_count = pick(0, 12);
    const int span = 2 * p.search_radius + 1;  // |hx| <= 2S+1
    std::vector<PoiRecord> records(static_cast<std::size_t>(p.blocks * p.blocks));
    for (PoiRecord& r : records) {
      r = PoiRecord{};
      r.status = static_cast<std::uint8_t>(pick(0, 2));
      if (r.status != kAccepted) continue;
      // Clustered like real flow (the filter's window matters), with outliers.
      const int cx = pick(-span, span), cy = pick(-span, span);
      r.hx = static_cast<std::int8_t>(pick(0, 3) ? cx / 3 + pick(-1, 1) : cx);
      r.hy = static_cast<std::int8_t>(pick(0, 3) ? cy / 3 + pick(-1, 1) : cy);
    }
    const FrameResult want = estimate_flow(records, p);
    std::vector<pxflow_poi_record> core(records.size());
    std::memcpy(core.data(), records.data(), records.size() * sizeof(PoiRecord));
    const pxflow_param_block q = spec_params(p);
    pxflow_estimate got;
    pxflow_estimate_flow(core.data(), static_cast<std::uint32_t>(core.size()), &q,
                         pxflow_window_mean_float, &got);
    INFO("round " << round << ", S " << p.search_radius << ", B " << p.blocks << ", HF "
                  << p.hist_filter);
    REQUIRE(std::bit_cast<std::uint32_t>(got.flow_x) == std::bit_cast<std::uint32_t>(want.flow_x));
    REQUIRE(std::bit_cast<std::uint32_t>(got.flow_y) == std::bit_cast<std::uint32_t>(want.flow_y));
    REQUIRE(got.quality == want.quality);
    REQUIRE(got.meancount == want.meancount);
  }
}

TEST_CASE("spec core: the C++ key table is the parameter block's order", "[spec]") {
  // Each field set to its own index + 100 in turn: the block's field at the table's position,
  // and only that one, carries it (flags carry 1).
  STATIC_REQUIRE(sizeof(pxflow_param_block) == PXFLOW_PARAM_FIELDS * sizeof(std::uint32_t));
  REQUIRE(param_fields().size() == PXFLOW_PARAM_FIELDS);
  for (std::size_t i = 0; i < param_fields().size(); ++i) {
    INFO("key " << param_fields()[i].key);
    Params p;
    const Params base = p;
    param_fields()[i].set(p, param_fields()[i].number ? int(i) + 100 : !param_fields()[i].get(p));
    const pxflow_param_block q = spec_params(p), b = spec_params(base);
    std::uint32_t got[PXFLOW_PARAM_FIELDS], was[PXFLOW_PARAM_FIELDS];
    std::memcpy(got, &q, sizeof got);
    std::memcpy(was, &b, sizeof was);
    for (std::size_t k = 0; k < PXFLOW_PARAM_FIELDS; ++k) CHECK((got[k] != was[k]) == (k == i));
    CHECK(static_cast<int>(got[i]) == param_fields()[i].get(p));
  }
}
