// pxflow vectors: the same bytes for a seed on every run, and `vectors verify` catching a
// one-bit flip with check's mismatch line (exit 1), a file of the wrong size (exit 2).
#include <catch2/catch.hpp>

#include "run_program.hpp"

using namespace pxflow::test;

TEST_CASE("pxflow vectors writes the same bytes for a seed", "[dut][vectors]") {
  TempDir a, b;
  for (const TempDir* d : {&a, &b}) {
    const auto r = run_pxflow({"vectors", "--out", d->path(""), "--cases", "6", "--seed", "9",
                               "--profile", "px4flow-head"});
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
  }
  for (const char* f : {"manifest.json", "frames.bin", "records.bin", "flow.bin"}) {
    INFO(f);
    CHECK_FALSE(slurp(a.path(f)).empty());
    CHECK(slurp(a.path(f)) == slurp(b.path(f)));
  }
  CHECK(slurp(a.path("records.bin")).size() == 6u * 25u * 32u);  // px4flow-head: 25 POIs
  CHECK(slurp(a.path("frames.bin")).size() == 6u * 2u * 64u * 64u);
}

TEST_CASE("pxflow vectors verify catches a one-bit flip and a wrong size", "[dut][vectors]") {
  TempDir d;
  REQUIRE(run_pxflow({"vectors", "--out", d.path(""), "--cases", "4"}).exit_code == 0);
  const auto same = run_pxflow({"vectors", "verify", d.path(""), d.path("records.bin")});
  CHECK(same.exit_code == 0);
  std::string flipped = slurp(d.path("records.bin"));
  flipped[64 * 32 + 5 * 32 + 10] ^= 0x01;  // pair 1, POI 5, the low byte of sad
  d.write("flipped.bin", flipped);
  const auto bad = run_pxflow({"vectors", "verify", d.path(""), d.path("flipped.bin")});
  INFO(bad.out << bad.err);
  CHECK(bad.exit_code == 1);
  CHECK_THAT(bad.out,
             Catch::Contains("FAIL") && Catch::Contains("poi=5") && Catch::Contains("field=sad"));
  d.write("short.bin", flipped.substr(0, 100));
  const auto size = run_pxflow({"vectors", "verify", d.path(""), d.path("short.bin")});
  CHECK(size.exit_code == 2);
  CHECK(size.err_lines() == 1);
}
