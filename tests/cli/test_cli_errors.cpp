// Bad input to `pxflow flow`: one clear line on stderr naming the culprit, exit code 2, and
// nothing on stdout (no partial JSON). Runs the real binary.
#include <catch2/catch.hpp>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "bad_input.hpp"
#include "run_program.hpp"
#include "synthetic.hpp"

using namespace pxflow;
using test::require_bad_input;
using test::run_pxflow;

namespace {

void write_png(const std::string& path, int w, int h, int type = CV_8UC1) {
  cv::Mat m(h, w, type);
  cv::randu(m, 0, type == CV_32FC1 ? 1.0 : 255.0);
  REQUIRE(cv::imwrite(path, m));
}

struct Files {
  test::TempDir dir;
  std::string good, good2, other_size, tiny, raw;
  Files() {
    good = dir.path("a.png"), good2 = dir.path("b.png");
    write_png(good, 64, 64);
    write_png(good2, 64, 64);
    write_png(other_size = dir.path("c.png"), 80, 64);
    write_png(tiny = dir.path("tiny.png"), 16, 16);
    raw = dir.path("a.raw");
    dir.write("a.raw", std::string(64 * 64, '\x40'));
  }
};

}  // namespace

TEST_CASE("missing, empty, directory and unreadable inputs", "[cli][errors]") {
  Files f;
  require_bad_input({"flow", f.dir.path("nope.png"), f.good}, "nope.png: no such file");
  f.dir.write("empty.png", "");
  require_bad_input({"flow", f.good, f.dir.path("empty.png")}, "empty.png: file is empty");
  require_bad_input({"flow", f.dir.path(""), f.good}, "is a directory");
}

TEST_CASE("corrupt, truncated and unsupported images", "[cli][errors]") {
  Files f;
  Rng rng(1);
  std::string noise(4096, '\0');
  for (auto& c : noise) c = static_cast<char>(rng.uniform(0, 255));
  f.dir.write("corrupt.png", noise);
  require_bad_input({"flow", f.dir.path("corrupt.png"), f.good}, "corrupt.png: cannot decode");

  std::ifstream in(f.good, std::ios::binary);
  std::string png((std::istreambuf_iterator<char>(in)), {});
  f.dir.write("truncated.png", png.substr(0, png.size() / 2));
  require_bad_input({"flow", f.good, f.dir.path("truncated.png")}, "truncated.png: cannot decode");

  write_png(f.dir.path("deep.png"), 64, 64, CV_16UC1);
  require_bad_input({"flow", f.dir.path("deep.png"), f.good}, "16-bit");
  write_png(f.dir.path("float.tiff"), 64, 64, CV_32FC1);
  require_bad_input({"flow", f.dir.path("float.tiff"), f.good}, "8-bit");
}

TEST_CASE("absurd sizes are refused before anything is allocated", "[cli][errors]") {
  Files f;
  // A PNG whose header declares 100000 x 100000 pixels (the rest is never read).
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\0\0\0\x0dIHDR", 8);
  png += std::string("\x00\x01\x86\xa0\x00\x01\x86\xa0\x08\x00\x00\x00\x00", 13);
  png += std::string(64, '\0');
  f.dir.write("bomb.png", png);
  require_bad_input({"flow", f.dir.path("bomb.png"), f.good},
                    "size 100000x100000: each side must be 1..16384");
  // Both sides in range, too many pixels: the message names that limit, never the sides.
  require_bad_input({"flow", "--size", "16384x16384", f.raw, f.raw},
                    "size 16384x16384 is 268435456 pixels, more than the supported 67108864");
  require_bad_input({"flow", "--size", "100000x100000", f.raw, f.raw}, "--size");
  require_bad_input({"flow", "--size", "64x", f.raw, f.raw}, "--size");
  require_bad_input({"flow", "--size", "sixty", f.raw, f.raw}, "--size");
}

TEST_CASE("raw files need --size and exactly W*H bytes", "[cli][errors]") {
  Files f;
  require_bad_input({"flow", f.raw, f.raw}, "needs --size");
  require_bad_input({"flow", "--size", "64x32", f.raw, f.raw}, "holds 4096 bytes");
  // With --size every input is raw, whatever its name: a PNG is then the wrong number of bytes.
  require_bad_input({"flow", "--size", "64x64", f.good, f.good2}, "but --size 64x64 needs 4096");
}

TEST_CASE("frames that do not fit each other or the profile", "[cli][errors]") {
  Files f;
  require_bad_input({"flow", f.good, f.other_size}, "frames differ in size");
  require_bad_input({"flow", f.tiny, f.tiny}, "too small");
  require_bad_input({"flow", "--set", "width=80", f.good, f.good2}, "--set asks for 80x64");
  require_bad_input({"flow", "--set", "search_radius=31", f.good, f.good2}, "too small");
}

TEST_CASE("unknown names and malformed parameters", "[cli][errors]") {
  Files f;
  require_bad_input({"flow", "--profile", "px4flow-99", f.good, f.good2},
                    "unknown profile 'px4flow-99'");
  require_bad_input({"flow", "--set", "colour=1", f.good, f.good2}, "unknown parameter 'colour'");
  require_bad_input({"flow", "--set", "search_radius", f.good, f.good2}, "KEY=VALUE");
  require_bad_input({"flow", "--set", "search_radius=four", f.good, f.good2}, "search_radius");
  require_bad_input({"flow", "--set", "search_radius=4.5", f.good, f.good2}, "search_radius");
  require_bad_input({"flow", "--set", "search_radius=0", f.good, f.good2}, "search_radius");
  require_bad_input({"flow", "--set", "tile=16", f.good, f.good2}, "tile");
  require_bad_input({"flow", "--set", "hist_filter=2", f.good, f.good2}, "hist_filter");
  require_bad_input({"flow", "--set", "sad_threshold=70000", f.good, f.good2}, "sad_threshold");
  require_bad_input({"flow", "--backend", "cuda-magic", f.good, f.good2},
                    "unknown backend 'cuda-magic'");
  require_bad_input({"flow", "--frobnicate", f.good, f.good2}, "frobnicate");
  // Refused before the command prints anything (bench's header included).
  require_bad_input({"bench", "--backends", "ref-original,nope"}, "unknown backend 'nope'");
  require_bad_input({"flow", f.good}, "NEXT");
  require_bad_input({"teleport"}, "teleport");
}
