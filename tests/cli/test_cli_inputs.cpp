// Inputs as users give them (issue 23 item 5): a pipe (bash's <(...), /dev/stdin, a FIFO) reads
// like the file it carries, a device that never ends is refused, a folder where a file belongs
// "is a directory" for every option that reads a file, and the pairs of --pairs may differ in
// size. Runs the real binary, through bash where the shell makes the pipe.
#include <sys/stat.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "bad_input.hpp"
#include "build_paths.hpp"
#include "run_program.hpp"
#include "synthetic.hpp"

using namespace pxflow;
using nlohmann::json;
using test::require_bad_input;
using test::run_pxflow;

namespace {

// Raw 32x32 noise frames a.raw and b.raw, and the same pixels as a.png and b.png.
struct Frames {
  test::TempDir dir;
  std::string a = dir.path("a.raw"), b = dir.path("b.raw");
  Frames() {
    Rng rng(5);
    for (const char* name : {"a", "b"}) {
      cv::Mat m(32, 32, CV_8UC1);
      for (int i = 0; i < m.rows * m.cols; ++i) m.data[i] = static_cast<uchar>(rng.uniform(0, 255));
      dir.write(std::string(name) + ".raw", std::string(m.datastart, m.dataend));
      REQUIRE(cv::imwrite(dir.path(std::string(name) + ".png"), m));
    }
  }
};

test::RunResult bash(const std::string& command) {
  return test::run_program("/bin/bash", {"-c", command});
}

std::string shell_quoted(const std::string& path) { return "'" + path + "'"; }

// What a flow JSON says of the frames, without the names it read them under.
json estimate(const std::string& out) {
  json j = json::parse(out);
  j.erase("inputs");
  return j;
}

}  // namespace

TEST_CASE("a pipe is an input like the file it carries", "[cli][inputs]") {
  Frames f;
  const std::string pxflow = shell_quoted(build_paths::pxflow);
  const auto files = run_pxflow({"flow", "--size", "32x32", "--json", "-", f.a, f.b});
  REQUIRE(files.exit_code == 0);

  // bash's process substitution: /dev/fd/N, a pipe.
  const auto raw = bash(pxflow + " flow --size 32x32 --json - <(cat " + shell_quoted(f.a) +
                        ") <(cat " + shell_quoted(f.b) + ")");
  INFO(raw.err);
  REQUIRE(raw.exit_code == 0);
  CHECK(estimate(raw.out) == estimate(files.out));
  // An image through a pipe decodes as the file does.
  const auto png = bash(pxflow + " flow --json - <(cat " + shell_quoted(f.dir.path("a.png")) +
                        ") <(cat " + shell_quoted(f.dir.path("b.png")) + ")");
  INFO(png.err);
  REQUIRE(png.exit_code == 0);
  CHECK(estimate(png.out) == estimate(files.out));

  // A FIFO as SOURCE, and /dev/stdin: raw frames back to back, one line per pair.
  const std::string fifo = f.dir.path("frames.fifo");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const auto seq = bash("cat " + shell_quoted(f.a) + " " + shell_quoted(f.b) + " " +
                        shell_quoted(f.a) + " > " + shell_quoted(fifo) + " & " + pxflow +
                        " flow --size 32x32 --jsonl - " + shell_quoted(fifo));
  INFO(seq.err);
  CHECK(seq.exit_code == 0);
  CHECK(std::count(seq.out.begin(), seq.out.end(), '\n') == 2);
  // A list of pairs through a pipe: its relative paths are the shell's, from the working folder.
  const auto list = bash("cd " + shell_quoted(f.dir.path("")) + " && " + pxflow +
                         " flow --size 32x32 --jsonl - --pairs <(echo a.raw b.raw)");
  INFO(list.err);
  REQUIRE(list.exit_code == 0);
  CHECK(estimate(list.out) == estimate(files.out));
  const auto stdin_seq = bash("cat " + shell_quoted(f.a) + " " + shell_quoted(f.b) + " | " +
                              pxflow + " flow --size 32x32 --jsonl - /dev/stdin");
  INFO(stdin_seq.err);
  CHECK(stdin_seq.exit_code == 0);
  CHECK(std::count(stdin_seq.out.begin(), stdin_seq.out.end(), '\n') == 1);
}

TEST_CASE("a device that never ends is refused, not read", "[cli][inputs]") {
  Frames f;
  require_bad_input({"flow", "--size", "32x32", "/dev/zero", f.b},
                    "/dev/zero: is a character device");
  require_bad_input({"flow", "--size", "32x32", "--jsonl", "-", "/dev/urandom"},
                    "/dev/urandom: is a character device");
  // A pipe longer than one raw frame is refused once it holds more, not read to its end.
  const auto endless = bash(shell_quoted(build_paths::pxflow) +
                            " flow --size 32x32 <(cat /dev/zero) " + shell_quoted(f.b));
  CHECK(endless.exit_code == 2);
  CHECK(endless.err.find("holds more than 1024 bytes, but --size 32x32 needs 1024") !=
        std::string::npos);
}

TEST_CASE("a folder where a file belongs is a directory, whatever the option", "[cli][inputs]") {
  Frames f;
  const std::string dir = f.dir.path("folder");
  REQUIRE(::mkdir(dir.c_str(), 0755) == 0);
  require_bad_input({"flow", "--size", "32x32", f.a, dir}, dir + ": is a directory");
  require_bad_input({"flow", "--pairs", dir}, "--pairs " + dir + ": is a directory");
  require_bad_input({"merge", "--json", f.dir.path("m.json"), dir}, dir + ": is a directory");
  require_bad_input({"report", "--out", f.dir.path("r"), "--check-json", dir, "--no-accuracy"},
                    "--check-json " + dir + ": is a directory");
  require_bad_input({"report", "--out", f.dir.path("r"), "--bench-json", dir, "--no-accuracy"},
                    "--bench-json " + dir + ": is a directory");
}

TEST_CASE("flow --pairs: each pair is its own problem, of its own size", "[cli][inputs]") {
  Frames f;
  cv::Mat big(48, 40, CV_8UC1);
  cv::randu(big, 0, 255);
  REQUIRE(cv::imwrite(f.dir.path("c.png"), big));
  REQUIRE(cv::imwrite(f.dir.path("d.png"), big));
  f.dir.write("list.txt", "a.png b.png\nc.png d.png\n");
  const auto r = run_pxflow({"flow", "--pairs", f.dir.path("list.txt"), "--jsonl", "-"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::vector<std::pair<int, int>> sizes;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    const json j = json::parse(line);
    sizes.push_back({j["width"], j["height"]});
  }
  CHECK(sizes == std::vector<std::pair<int, int>>{{32, 32}, {40, 48}});
  // Within a pair the frames still share one size.
  f.dir.write("mixed.txt", "a.png c.png\n");
  require_bad_input({"flow", "--pairs", f.dir.path("mixed.txt")}, "frames differ in size");
}
