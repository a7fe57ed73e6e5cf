// pxflow vectors: the same bytes for a seed on every run, and `vectors verify` catching a
// one-bit flip with check's mismatch line (exit 1), a file of the wrong size (exit 2); --from a
// list of real pairs; the protocol page lists manifest.json's keys as they are.
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "build_paths.hpp"
#include "run_program.hpp"
#include "sample_data.hpp"

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

namespace {

// Every key of every object in `j`, at any depth.
void collect_keys(const nlohmann::json& j, std::set<std::string>& keys) {
  if (j.is_object())
    for (const auto& [key, value] : j.items()) keys.insert(key), collect_keys(value, keys);
  else if (j.is_array())
    for (const auto& value : j) collect_keys(value, keys);
}

}  // namespace

TEST_CASE("the protocol page names every key of manifest.json", "[dut][vectors]") {
  TempDir d;
  REQUIRE(run_pxflow({"vectors", "--out", d.path(""), "--cases", "2"}).exit_code == 0);
  std::set<std::string> written;
  collect_keys(nlohmann::json::parse(slurp(d.path("manifest.json"))), written);
  written.insert("from");  // in place of `seed` with --from (the last test case)
  // Section 9's bullet on manifest.json: every `word` of lower-case letters and '_' is a key.
  const std::string page = slurp(build_paths::protocol_page);
  const auto at = page.find("- `manifest.json`:");
  REQUIRE(at != std::string::npos);
  const std::string bullet = page.substr(at, page.find("\n- `", at + 1) - at);
  std::set<std::string> named;
  const std::regex word("`([a-z_]+)`");
  for (std::sregex_iterator m(bullet.begin(), bullet.end(), word), end; m != end; ++m)
    named.insert((*m)[1]);
  CHECK(named == written);
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

TEST_CASE("pxflow vectors verify reads a --format c folder", "[dut][vectors]") {
  TempDir d;
  for (const char* format : {"bin", "c"})
    REQUIRE(run_pxflow({"vectors", "--out", d.path(format), "--format", format, "--cases", "3",
                        "--seed", "5"})
                .exit_code == 0);
  // The C folder's header has every parameter of SPEC §1, T and GC included.
  const std::string header = slurp(d.path("c/pxflow_vectors.h"));
  for (const char* macro : {"PXV_T 8u", "PXV_GC 0u", "PXV_MINCOUNT", "PXV_HF", "PXV_POIS"})
    CHECK_THAT(header, Catch::Contains(std::string("#define ") + macro));
  const std::string records = d.path("bin/records.bin");
  const auto same = run_pxflow({"vectors", "verify", d.path("c"), records});
  INFO(same.out << same.err);
  CHECK(same.exit_code == 0);
  std::string flipped = slurp(records);
  flipped[64 * 32 + 5 * 32 + 10] ^= 0x01;  // pair 1, POI 5, the low byte of sad
  d.write("flipped.bin", flipped);
  const auto bad = run_pxflow({"vectors", "verify", d.path("c"), d.path("flipped.bin")});
  CHECK(bad.exit_code == 1);
  CHECK_THAT(bad.out, Catch::Contains("poi=5") && Catch::Contains("field=sad"));
  // A folder with a manifest but neither records file: one line naming both formats, exit 2.
  for (const char* folder : {"none", "damaged"})
    std::filesystem::create_directories(d.path(folder));
  d.write("none/manifest.json", slurp(d.path("c/manifest.json")));
  const auto none = run_pxflow({"vectors", "verify", d.path("none"), records});
  CHECK(none.exit_code == 2);
  CHECK(none.err_lines() == 1);
  CHECK_THAT(none.err, Catch::Contains("--format bin") && Catch::Contains("--format c"));
  // A damaged array: one line, exit 2.
  std::string arrays = slurp(d.path("c/pxflow_vectors.c"));
  arrays.insert(arrays.find('{', arrays.find("pxv_records[")) + 1, "x");
  d.write("damaged/manifest.json", slurp(d.path("c/manifest.json")));
  d.write("damaged/pxflow_vectors.c", arrays);
  const auto damaged = run_pxflow({"vectors", "verify", d.path("damaged"), records});
  INFO(damaged.err);
  CHECK(damaged.exit_code == 2);
  CHECK(damaged.err_lines() == 1);
}

TEST_CASE("the protocol page names every PXV_ macro of the C header", "[dut][vectors]") {
  TempDir d;
  REQUIRE(run_pxflow({"vectors", "--out", d.path(""), "--format", "c", "--cases", "1"}).exit_code ==
          0);
  const auto names = [](const std::string& text, const std::regex& pattern) {
    std::set<std::string> found;
    for (std::sregex_iterator m(text.begin(), text.end(), pattern), end; m != end; ++m)
      found.insert((*m)[1]);
    return found;
  };
  const std::set<std::string> defined =
      names(slurp(d.path("pxflow_vectors.h")), std::regex("#define (PXV_[A-Z]+) "));
  const std::string page = slurp(build_paths::protocol_page);
  const auto at = page.find("## 9.");
  REQUIRE(at != std::string::npos);
  const std::string section = page.substr(at, page.find("\n## ", at + 1) - at);
  CHECK(names(section, std::regex("`(PXV_[A-Z]+)`")) == defined);
}

TEST_CASE("pxflow vectors --from a list of real pairs: flow bits equal pxflow flow's",
          "[dut][vectors]") {
  TempDir d;
  const std::string data = std::string(pxflow::kSampleDataDir) + "/";
  d.write("list.txt", data + "rubberwhale1.png " + data + "rubberwhale2.png\n");
  // The vectors' own folder: a folder of other files (the list) is refused (owned_folder.hpp).
  const auto r = run_pxflow({"vectors", "--out", d.path("vec"), "--from", d.path("list.txt")});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const auto flow =
      run_pxflow({"flow", "--json", "-", data + "rubberwhale1.png", data + "rubberwhale2.png"});
  REQUIRE(flow.exit_code == 0);
  const auto bits = [](const std::string& text, const std::string& key) {
    const auto at = text.find("\"" + key + "\"");
    REQUIRE(at != std::string::npos);
    const auto open = text.find('"', text.find(':', at)) + 1;
    std::string v = text.substr(open, text.find('"', open) - open);
    return v.rfind("0x", 0) == 0 ? v.substr(2) : v;
  };
  const std::string manifest = slurp(d.path("vec/manifest.json"));
  CHECK(bits(manifest, "flow_x_bits") == bits(flow.out, "flow_x_bits"));
  CHECK(bits(manifest, "flow_y_bits") == bits(flow.out, "flow_y_bits"));
  CHECK(slurp(d.path("vec/frames.bin")).size() == 2u * 584u * 388u);
  CHECK(run_pxflow({"vectors", "verify", d.path("vec"), d.path("vec/records.bin")}).exit_code == 0);
  // --from gives the pairs: --seed (or --cases) beside it would do nothing, so it is refused.
  const auto both =
      run_pxflow({"vectors", "--out", d.path("vec"), "--from", d.path("list.txt"), "--seed", "3"});
  CHECK(both.exit_code == 2);
  CHECK(both.err_lines() == 1);
}
