// `pxflow flow` on sequences: every consecutive pair of a video, a folder, a glob, raw frames on
// standard input and a list file of pairs, each per-pair object byte for byte what one
// `pxflow flow --json` call per pair prints on the same frames extracted to raw files; the CSV,
// the summary, the fast start without the OpenCV module, and the options that make frames fit.
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <sstream>

#include "build_paths.hpp"
#include "flow_report.hpp"
#include "frame_ops.hpp"
#include "run_program.hpp"
#include "sample_frames.hpp"

using nlohmann::json;
using pxflow::test::kData;
using pxflow::test::run_program;
using pxflow::test::run_pxflow;
using pxflow::test::TempDir;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The first `count` frames of a video in gray (OpenCV directly, not through pxflow), each
// written to dir/f-NNN.raw; returns the paths and sets the frame size.
std::vector<std::string> extract_frames(const std::string& video, int count, const TempDir& dir,
                                        std::string& size) {
  cv::VideoCapture cap(video);
  REQUIRE(cap.isOpened());
  std::vector<std::string> paths;
  cv::Mat frame, gray;
  for (int n = 0; n < count && cap.read(frame); ++n) {
    cv::cvtColor(frame, gray, cv::COLOR_BGR2GRAY);
    REQUIRE(gray.isContinuous());
    char name[32];
    std::snprintf(name, sizeof name, "f-%03d.raw", n);
    dir.write(name, std::string(reinterpret_cast<const char*>(gray.data), gray.total()));
    paths.push_back(dir.path(name));
    size = std::to_string(gray.cols) + "x" + std::to_string(gray.rows);
  }
  REQUIRE(static_cast<int>(paths.size()) == count);
  return paths;
}

// `single` (one pair's --json line) with its input names replaced by the sequence's.
std::string renamed(std::string single, const std::string& prev_path, const std::string& next_path,
                    const std::string& prev_name, const std::string& next_name) {
  using ordered = nlohmann::ordered_json;  // prev before next, as pxflow writes them (crop follows)
  std::string from = ordered{{"prev", prev_path}, {"next", next_path}}.dump();
  std::string to = ordered{{"prev", prev_name}, {"next", next_name}}.dump();
  from.pop_back(), to.pop_back();  // the closing brace: "crop" and "bin" follow
  const auto at = single.find("\"inputs\":" + from);
  REQUIRE(at != std::string::npos);
  return single.replace(at + 9, from.size(), to);
}

}  // namespace

TEST_CASE("a video's pairs equal one flow --json call per pair, byte for byte", "[cli][sequence]") {
  for (auto [video, backend] : {std::pair{"vtest.avi", "cpu"}, {"tree.avi", "ref-original"}}) {
    CAPTURE(video, backend);
    TempDir dir;
    std::string size;
    const int pairs = 10;
    const auto frames = extract_frames(kData + "/" + video, pairs + 1, dir, size);
    const auto seq = run_pxflow(
        {"flow", "--backend", backend, "--max-pairs", "10", "--jsonl", "-", kData + "/" + video});
    INFO("stderr: " << seq.err);
    REQUIRE(seq.exit_code == 0);
    const auto got = lines_of(seq.out);
    REQUIRE(got.size() == static_cast<std::size_t>(pairs));
    for (int i = 0; i < pairs; ++i) {
      const auto one = run_pxflow(
          {"flow", "--backend", backend, "--size", size, "--json", "-", frames[i], frames[i + 1]});
      REQUIRE(one.exit_code == 0);
      const auto expected = lines_of(one.out);
      REQUIRE(expected.size() == 1);
      const std::string name = std::string(video) + "#";
      CHECK(got[i] == renamed(expected[0], frames[i], frames[i + 1], name + std::to_string(i),
                              name + std::to_string(i + 1)));
    }
    // The summary goes to stderr when stdout carries the objects.
    CHECK(seq.err.find("10 pairs (11 frames)") != std::string::npos);
    CHECK(seq.err.find("pairs/s") != std::string::npos);
  }
}

TEST_CASE("folder, glob, raw stdin and a list file give the same pairs", "[cli][sequence]") {
  TempDir dir;
  std::string size;
  const auto frames = extract_frames(kData + "/tree.avi", 4, dir, size);
  // Each source's objects less the input names, which differ by source.
  auto objects = [](const pxflow::test::RunResult& r) {
    INFO("stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    std::vector<std::string> out;
    for (const auto& line : lines_of(r.out)) {
      json j = json::parse(line);
      j.erase("inputs");
      out.push_back(j.dump());
    }
    return out;
  };
  const auto folder = objects(run_pxflow({"flow", "--size", size, "--jsonl", "-", dir.path("")}));
  REQUIRE(folder.size() == 3);
  CHECK(objects(run_pxflow({"flow", "--size", size, "--jsonl", "-", dir.path("f-*.raw")})) ==
        folder);
  const std::string cat = "cat " + frames[0] + " " + frames[1] + " " + frames[2] + " " + frames[3];
  const auto piped = run_program("/bin/sh", {"-c", cat + " | " + build_paths::pxflow +
                                                       " flow --size " + size + " --jsonl - -"});
  CHECK(objects(piped) == folder);
  CHECK(json::parse(lines_of(piped.out)[1])["inputs"]["prev"] == "-#1");
  dir.write("pairs.txt", "# prev next\nf-000.raw f-001.raw\n\nf-001.raw f-002.raw\n");
  const auto listed = objects(
      run_pxflow({"flow", "--size", size, "--jsonl", "-", "--pairs", dir.path("pairs.txt")}));
  CHECK(listed == std::vector<std::string>(folder.begin(), folder.begin() + 2));
  // A partial last frame on stdin is one line, exit 2.
  const auto partial =
      run_program("/bin/sh", {"-c", "head -c 5000 " + frames[0] + " | " + build_paths::pxflow +
                                        " flow --size " + size + " -"});
  CHECK(partial.exit_code == 2);
  CHECK(partial.err.find("ends in a partial frame") != std::string::npos);
}

TEST_CASE("CSV rows, text lines, files and the sequence errors", "[cli][sequence]") {
  TempDir dir;
  std::string size;
  extract_frames(kData + "/tree.avi", 3, dir, size);
  // Outputs inside the folder read are refused (the next run would read them as frames).
  const auto inside =
      run_pxflow({"flow", "--size", size, "--csv", dir.path("out.csv"), dir.path("")});
  CHECK(inside.exit_code == 2);
  CHECK(inside.err.find("pxflow never writes where it reads") != std::string::npos);
  TempDir out_dir;
  const auto text = run_pxflow({"flow", "--size", size, "--csv", out_dir.path("out.csv"), "--jsonl",
                                out_dir.path("out.jsonl"), dir.path("")});
  REQUIRE(text.exit_code == 0);
  const auto out = lines_of(text.out);
  REQUIRE(out.size() == 3);  // one line per pair, then the summary
  CHECK(out[0].rfind("pair 0  ", 0) == 0);
  CHECK(out[2].find("2 pairs (3 frames)") != std::string::npos);
  const auto csv = lines_of(pxflow::test::slurp(out_dir.path("out.csv")));
  REQUIRE(csv.size() == 3);
  CHECK(csv[0].rfind("pair,prev,next,crop,bin,backend,profile,width,height,flow_x,flow_y,", 0) ==
        0);
  CHECK(csv[1].find(",,1,ref-original,px4flow-64,") != std::string::npos);  // no crop, bin 1
  const auto jsonl = lines_of(pxflow::test::slurp(out_dir.path("out.jsonl")));
  REQUIRE(jsonl.size() == 2);
  CHECK(csv[2].find(json::parse(jsonl[1])["flow_x_bits"].get<std::string>()) != std::string::npos);

  const auto json_seq = run_pxflow({"flow", "--size", size, "--json", "-", dir.path("")});
  CHECK(json_seq.exit_code == 2);
  CHECK(json_seq.err.find("use --jsonl") != std::string::npos);
  const auto two_stdout =
      run_pxflow({"flow", "--size", size, "--jsonl", "-", "--csv", "-", dir.path("")});
  CHECK(two_stdout.exit_code == 2);
  CHECK(two_stdout.err_lines() == 1);
  const auto draw_file =
      run_pxflow({"flow", "--size", size, "--draw", dir.path("x.png"), dir.path("")});
  CHECK(draw_file.exit_code == 2);
  CHECK(draw_file.err.find("existing folder") != std::string::npos);
}

TEST_CASE("flow --json names what ran, the inputs, params, status names and version",
          "[cli][json]") {
  const std::string a = kData + "/rubberwhale1.png", b = kData + "/rubberwhale2.png";
  const auto r = run_pxflow({"flow", "--json", "-", "--backend", "cpu", a, b});
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(r.out);
  CHECK(j["backend"] == "cpu");
  CHECK(j["implementation"] != "cpu");  // the ISA the cpu row chose
  CHECK(j["device"] == "host");
  CHECK(j["inputs"]["prev"] == a);
  CHECK(j["width"] == 584);
  CHECK(j["params"]["search_radius"] == 4);
  CHECK(j["pxflow"]["version"].is_string());
  CHECK(j["pois"][0].contains("status_name"));
  const auto text = run_pxflow({"flow", "--backend", "cpu", a, b});
  CHECK(text.out.find("backend   cpu -> " + j["implementation"].get<std::string>()) !=
        std::string::npos);
  CHECK(text.out.find("time      ") != std::string::npos);
  // MINCOUNT: no POI can pass FT=6121, so the flow is 0 and the summary says why.
  const auto zero = run_pxflow({"flow", "--set", "feature_threshold=6121", a, b});
  CHECK(zero.out.find("flow is 0 because only 0 POIs were accepted and MINCOUNT=10") !=
        std::string::npos);
}

TEST_CASE("flow records --crop and --bin in its JSON, JSON lines, CSV and picture caption",
          "[cli][json]") {
  const std::string a = kData + "/rubberwhale1.png", b = kData + "/rubberwhale2.png";
  TempDir dir;
  const auto r = run_pxflow({"flow", "--backend", "ref-local", "--crop", "128x128+200+100", "--bin",
                             "2", "--json", dir.path("one.json"), "--jsonl", dir.path("one.jsonl"),
                             "--csv", dir.path("one.csv"), a, b});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  for (const char* file : {"one.json", "one.jsonl"}) {
    CAPTURE(file);
    const json j = json::parse(pxflow::test::slurp(dir.path(file)));
    CHECK(j["inputs"]["prev"] == a);
    CHECK(j["inputs"]["crop"] == "128x128+200+100");
    CHECK(j["inputs"]["bin"] == 2);
    CHECK(j["width"] == 64);
  }
  const auto csv = lines_of(pxflow::test::slurp(dir.path("one.csv")));
  REQUIRE(csv.size() == 2);
  CHECK(csv[1].find(",128x128+200+100,2,ref-local,px4flow-64,64,64,") != std::string::npos);
  // Without them: crop null, bin 1 (the keys are always there).
  const json plain = json::parse(run_pxflow({"flow", "--json", "-", a, b}).out);
  CHECK(plain["inputs"]["crop"].is_null());
  CHECK(plain["inputs"]["bin"] == 1);
  // The caption of --draw, as flow_report.cpp makes it for the picture.
  pxflow::cli::PairRun run;
  run.prev_name = a, run.next_name = b, run.backend = "ref-local", run.profile = "px4flow-64";
  pxflow::parse_crop("128x128+200+100", run.shaping);
  run.shaping.bin = 2;
  CHECK(pxflow::cli::draw_caption(run).frames ==
        "rubberwhale1.png -> rubberwhale2.png, crop 128x128+200+100, bin 2");
  run.shaping = {};
  CHECK(pxflow::cli::draw_caption(run).frames == "rubberwhale1.png -> rubberwhale2.png");
}

TEST_CASE("flow's JSON is the same bytes for --threads 1 and --threads 2", "[cli][json]") {
  const std::string a = kData + "/rubberwhale1.png", b = kData + "/rubberwhale2.png";
  // Every multi-threaded row this build may have; the reference rows take --threads too.
  for (const std::string backend : {"ref-local", "cpu", "swar"}) {
    CAPTURE(backend);
    std::string out[2];
    for (int t = 1; t <= 2; ++t) {
      const auto r = run_pxflow(
          {"flow", "--json", "-", "--backend", backend, "--threads", std::to_string(t), a, b});
      if (r.exit_code == 2 && r.err.find("unknown backend") != std::string::npos) break;
      INFO(r.err);
      REQUIRE(r.exit_code == 0);
      out[t - 1] = r.out;
    }
    CHECK(out[0] == out[1]);
  }
}

TEST_CASE("a frame too large for GAP8's L1 names --crop and --bin, which make it fit",
          "[cli][gap8]") {
  const std::string a = kData + "/rubberwhale1.png", b = kData + "/rubberwhale2.png";
  const auto big = run_pxflow({"flow", "--backend", "gap8-fast", a, b});
  CHECK(big.exit_code == 2);
  CHECK(big.err_lines() == 1);
  CHECK(big.err.find("does not fit L1") != std::string::npos);
  CHECK(big.err.find("--crop WxH+X+Y") != std::string::npos);
  CHECK(big.err.find("--bin N") != std::string::npos);
  const auto cropped = run_pxflow(
      {"flow", "--backend", "gap8-fast", "--json", "-", "--crop", "64x64+200+150", a, b});
  REQUIRE(cropped.exit_code == 0);
  CHECK(json::parse(cropped.out)["width"] == 64);
  const auto binned = run_pxflow({"flow", "--backend", "gap8-fast", "--json", "-", "--crop",
                                  "512x256+0+0", "--bin", "4", a, b});
  REQUIRE(binned.exit_code == 0);
  CHECK(json::parse(binned.out)["width"] == 128);
  CHECK(json::parse(binned.out)["height"] == 64);
  // pxflow gap8 likewise: checked before any work, exit 2, and the same options make it fit.
  const auto study = run_pxflow({"gap8", "--cores", "1", "--variant", "local", a, b});
  CHECK(study.exit_code == 2);
  CHECK(study.err_lines() == 1);
  CHECK(study.err.find("does not fit L1") != std::string::npos);
  CHECK(study.err.find("--crop WxH+X+Y") != std::string::npos);
  const auto fits = run_pxflow({"gap8", "--cores", "1", "--variant", "local", "--crop",
                                "128x128+200+100", "--bin", "2", a, b});
  CHECK(fits.exit_code == 0);
  CHECK(fits.out.find("(--crop 128x128+200+100 --bin 2: 64x64)") != std::string::npos);
  const auto outside = run_pxflow({"flow", "--crop", "64x64+560+0", a, b});
  CHECK(outside.exit_code == 2);
  CHECK(outside.err.find("does not lie inside the 584x388 frame") != std::string::npos);
  const auto bad = run_pxflow({"flow", "--crop", "64x64", a, b});
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("is not WxH+X+Y") != std::string::npos);
}

TEST_CASE("commands that decode nothing run without the OpenCV module", "[cli][startup]") {
  TempDir dir;
  dir.write("a.bin", std::string(64 * 64, '\x40'));
  const std::string env = "PXFLOW_OPENCV_MODULE=" + dir.path("missing/libpxflow_opencv.so");
  const auto raw = run_program("/usr/bin/env", {env, build_paths::pxflow, "flow", "--size", "64x64",
                                                dir.path("a.bin"), dir.path("a.bin")});
  CHECK(raw.exit_code == 0);
  CHECK(run_program("/usr/bin/env", {env, build_paths::pxflow, "--version"}).exit_code == 0);
  const auto png = run_program(
      "/usr/bin/env",
      {env, build_paths::pxflow, "flow", kData + "/rubberwhale1.png", kData + "/rubberwhale2.png"});
  CHECK(png.exit_code == 2);
  CHECK(png.err_lines() == 1);
  CHECK(png.err.find("the OpenCV module, needed to decode images and video, is missing") !=
        std::string::npos);
  CHECK(png.err.find(dir.path("missing/libpxflow_opencv.so")) != std::string::npos);
  // Not a module at all: also one line, naming the file.
  dir.write("fake.so", "not an ELF file");
  const auto fake =
      run_program("/usr/bin/env", {"PXFLOW_OPENCV_MODULE=" + dir.path("fake.so"),
                                   build_paths::pxflow, "flow", kData + "/vtest.avi"});
  CHECK(fake.exit_code == 2);
  CHECK(fake.err_lines() == 1);
  CHECK(fake.err.find("fake.so cannot be loaded") != std::string::npos);
}
