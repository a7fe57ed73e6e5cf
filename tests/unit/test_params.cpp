// Profiles, overrides, validation and the POI grid (SPEC §1, §2).
#include <catch2/catch.hpp>

#include "errors.hpp"
#include "grid.hpp"
#include "params.hpp"
#include "registry.hpp"

using namespace pxflow;

TEST_CASE("profiles carry SPEC §1's values", "[params]") {
  const Params a = profile("px4flow-64");
  CHECK(a.width == 64);
  CHECK(a.height == 64);
  CHECK(a.search_radius == 4);
  CHECK(a.tile == 8);
  CHECK(a.blocks == 8);
  CHECK(a.feature_threshold == 40);
  CHECK(a.sad_threshold == 5000);
  CHECK(a.hist_filter);
  CHECK(a.min_count == 10);
  CHECK_FALSE(a.gyro_comp);
  const Params b = profile("px4flow-head");
  CHECK(b.search_radius == 8);
  CHECK(b.blocks == 5);
  CHECK_FALSE(b.hist_filter);
  CHECK(profile_names().front() == "px4flow-64");
  CHECK_THROWS_AS(profile("px4flow-65"), InputError);
}

TEST_CASE("every key can be overridden", "[params]") {
  Params p = profile("px4flow-64");
  set_param(p, "width", "128");
  set_param(p, "height", "96");
  set_param(p, "search_radius", "7");
  set_param(p, "blocks", "12");
  set_param(p, "feature_threshold", "0");
  set_param(p, "sad_threshold", "65535");
  set_param(p, "hist_filter", "0");
  set_param(p, "min_count", "3");
  set_param(p, "gyro_comp", "1");
  set_param(p, "tile", "8");
  CHECK(p.width == 128);
  CHECK(p.height == 96);
  CHECK(p.search_radius == 7);
  CHECK(p.blocks == 12);
  CHECK(p.feature_threshold == 0);
  CHECK(p.sad_threshold == 65535);
  CHECK_FALSE(p.hist_filter);
  CHECK(p.min_count == 3);
  CHECK(p.gyro_comp);
  CHECK_NOTHROW(validate(p));
  CHECK(param_keys().size() == 10);
}

TEST_CASE("malformed overrides are refused with the key in the message", "[params]") {
  Params p;
  CHECK_THROWS_WITH(set_param(p, "colour", "1"), Catch::Contains("unknown parameter 'colour'"));
  CHECK_THROWS_WITH(set_param(p, "search_radius", "abc"), Catch::Contains("search_radius"));
  CHECK_THROWS_AS(set_param(p, "search_radius", "4.5"), InputError);
  CHECK_THROWS_AS(set_param(p, "search_radius", ""), InputError);
  CHECK_THROWS_AS(set_param(p, "search_radius", " 4"), InputError);
  CHECK_THROWS_AS(set_param(p, "width", "99999999999"), InputError);
  CHECK_THROWS_AS(set_param(p, "hist_filter", "2"), InputError);
  CHECK(p == Params{});  // failed overrides leave the parameters unchanged
}

TEST_CASE("validation rejects every invalid combination of SPEC §1", "[params]") {
  auto bad = [](auto&& change) {
    Params p;
    change(p);
    return p;
  };
  CHECK_THROWS_WITH(validate(bad([](Params& p) { p.tile = 16; })), Catch::Contains("tile"));
  CHECK_THROWS_WITH(validate(bad([](Params& p) { p.search_radius = 0; })),
                    Catch::Contains("search_radius"));
  CHECK_THROWS_AS(validate(bad([](Params& p) { p.search_radius = 32; })), InputError);
  CHECK_THROWS_WITH(validate(bad([](Params& p) { p.blocks = 0; })), Catch::Contains("blocks"));
  CHECK_THROWS_AS(validate(bad([](Params& p) { p.blocks = 256; })), InputError);
  CHECK_THROWS_AS(validate(bad([](Params& p) { p.feature_threshold = -1; })), InputError);
  CHECK_THROWS_AS(validate(bad([](Params& p) { p.sad_threshold = 65536; })), InputError);
  CHECK_THROWS_AS(validate(bad([](Params& p) { p.min_count = -1; })), InputError);
  CHECK_THROWS_AS(validate(bad([](Params& p) { p.width = 100000; })), InputError);
  CHECK_THROWS_AS(validate(bad([](Params& p) { p.width = p.height = 10000; })), InputError);
  // S = 31 needs 2*32+8+1 = 73 pixels per side: 64x64 is too small, 73x73 is enough.
  CHECK_THROWS_WITH(validate(bad([](Params& p) { p.search_radius = 31; })),
                    Catch::Contains("too small"));
  CHECK_NOTHROW(validate(bad([](Params& p) { p.search_radius = 31, p.width = p.height = 73; })));
  CHECK_THROWS_AS(
      validate(bad([](Params& p) { p.search_radius = 31, p.width = 72, p.height = 73; })),
      InputError);
  CHECK_NOTHROW(validate(Params{}));
}

TEST_CASE("the grid follows SPEC §2's integer formula", "[grid]") {
  Params p;
  CHECK(grid_axis(64, p) == std::vector<int>{5, 11, 17, 23, 29, 35, 41, 47});
  const auto pois = poi_grid(p);
  REQUIRE(pois.size() == 64);
  CHECK(pois[1].x == 11);  // x inner, y outer
  CHECK(pois[1].y == 5);
  CHECK(pois[8].x == 5);
  CHECK(pois[8].y == 11);
  CHECK(poi_count(p) == 64);

  const Params head = profile("px4flow-head");
  CHECK(grid_axis(64, head) == std::vector<int>{9, 17, 25, 33, 41});
  // S = 3, 6, 7 give only 7 points at 64 pixels: kept as the firmware computes it.
  for (int s : {3, 6, 7}) {
    p.search_radius = s;
    CHECK(grid_axis(64, p).size() == 7);
  }
  // Larger frames: same formula per axis, never more than B points.
  p = Params{};
  p.width = 584;
  p.height = 388;
  CHECK(grid_axis(584, p) == std::vector<int>{5, 76, 147, 218, 289, 360, 431, 502});
  CHECK(grid_axis(388, p).size() == 8);
  // The smallest valid frame has exactly one POI per axis.
  p.width = p.height = 2 * 5 + 8 + 1;
  CHECK(grid_axis(p.width, p) == std::vector<int>{5});
}

TEST_CASE("check_batch names what is wrong with a frame view", "[params]") {
  const Params p = profile("px4flow-64");
  std::vector<std::uint8_t> pixels(64 * 64, 0);
  const FrameView good{64, 64, 64, pixels.data()};
  std::vector<PoiRecord> out(poi_count(p));
  const auto message = [&](FrameView prev) {
    const FramePair pair{prev, good};
    try {
      check_batch({&pair, 1}, p, out);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(message(good) == "accepted");
  CHECK(message({32, 64, 64, pixels.data()}) == "frame is 32x64 but the parameters say 64x64");
  CHECK(message({64, 64, 64, nullptr}) == "frame view has no pixels (a null pointer)");
  CHECK(message({64, 64, 63, pixels.data()}) == "frame view has a stride below its width");
}
