// `pxflow flow` on good input: the JSON contract of the foundation issue, text output, and the
// same answer from PNG, raw and colour versions of one frame pair.
#include <bit>
#include <catch2/catch.hpp>
#include <cstring>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "run_program.hpp"
#include "synthetic.hpp"

using namespace pxflow;
using nlohmann::json;
using test::run_pxflow;

namespace {

struct ShiftedPair {
  test::TempDir dir;
  OwnedPair op;
  ShiftedPair() {
    op = {"shift", 64, 64, std::vector<std::uint8_t>(64 * 64), {}};
    Rng rng(4);
    for (auto& v : op.prev) v = static_cast<std::uint8_t>(rng.uniform(0, 255));
    shift_into(op.prev, op.next, 64, 64, 2, -1, 9);
    write("prev", op.prev);
    write("next", op.next);
  }
  void write(const std::string& name, std::vector<std::uint8_t>& px) {
    const cv::Mat m(64, 64, CV_8UC1, px.data());
    REQUIRE(cv::imwrite(dir.path(name + ".png"), m));
    dir.write(name + ".raw", std::string(px.begin(), px.end()));
    cv::Mat bgr;
    cv::Mat channels[] = {m, m, m};
    cv::merge(channels, 3, bgr);  // gray in all three channels converts back exactly
    REQUIRE(cv::imwrite(dir.path(name + "-bgr.png"), bgr));
  }
};

json flow_json(const std::vector<std::string>& args) {
  const auto r = run_pxflow(args);
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.err.empty());
  REQUIRE(std::count(r.out.begin(), r.out.end(), '\n') == 1);  // exactly one JSON object
  return json::parse(r.out);
}

}  // namespace

TEST_CASE("flow --json prints the documented object", "[cli][json]") {
  ShiftedPair sp;
  for (const char* backend : {"ref-original", "ref-local", "ref-global"}) {
    CAPTURE(backend);
    const json j = flow_json({"flow", "--json", "-", "--backend", backend, sp.dir.path("prev.png"),
                              sp.dir.path("next.png")});
    for (const char* key : {"flow_x", "flow_y", "flow_x_bits", "flow_y_bits", "quality",
                            "meancount", "histx", "histy", "counts", "pois"})
      REQUIRE(j.contains(key));
    CHECK(j["flow_x"].get<double>() == 2.0);
    CHECK(j["flow_y"].get<double>() == -1.0);
    CHECK(j["flow_x_bits"] == "40000000");
    CHECK(j["flow_y_bits"] == "bf800000");
    CHECK(j["quality"] == 255);
    CHECK(j["meancount"] == 64);
    CHECK(j["histx"].size() == 19);
    CHECK(j["histx"][4 + 9] == 64);
    CHECK(j["histy"][-2 + 9] == 64);
    CHECK(j["counts"]["sad_ops"] == 91520);
    REQUIRE(j["pois"].size() == 64);
    const json& p = j["pois"][9];
    for (const char* key :
         {"x", "y", "status", "feature", "dx", "dy", "sad", "dir", "sub", "hx", "hy"})
      REQUIRE(p.contains(key));
    CHECK(p["x"] == 11);
    CHECK(p["y"] == 11);
    CHECK(p["status"] == 2);
    CHECK(p["dx"] == 2);
    CHECK(p["dy"] == -1);
    CHECK(p["sad"] == 0);
    CHECK(p["dir"] == 8);
    CHECK(p["sub"].size() == 8);
    CHECK(p["hx"] == 4);
    CHECK(p["hy"] == -2);
  }
  CHECK(flow_json({"flow", "--json", "-", "--backend", "ref-local", sp.dir.path("prev.png"),
                   sp.dir.path("next.png")})["counts"]["interpolations"] == 19200);
}

TEST_CASE("PNG, raw and colour inputs give identical JSON", "[cli][json]") {
  ShiftedPair sp;
  const json png =
      flow_json({"flow", "--json", "-", sp.dir.path("prev.png"), sp.dir.path("next.png")});
  const json raw = flow_json(
      {"flow", "--json", "-", "--size", "64x64", sp.dir.path("prev.raw"), sp.dir.path("next.raw")});
  const json bgr =
      flow_json({"flow", "--json", "-", sp.dir.path("prev-bgr.png"), sp.dir.path("next-bgr.png")});
  // The same bytes but for the input names.
  auto without_inputs = [](json j) {
    j.erase("inputs");
    return j;
  };
  CHECK(without_inputs(png) == without_inputs(raw));
  CHECK(without_inputs(png) == without_inputs(bgr));
}

TEST_CASE("profile and --set reach the kernel", "[cli][json]") {
  ShiftedPair sp;
  const json head = flow_json({"flow", "--json", "-", "--profile", "px4flow-head",
                               sp.dir.path("prev.png"), sp.dir.path("next.png")});
  CHECK(head["pois"].size() == 25);
  CHECK(head["histx"].size() == 2 * (2 * 8 + 1) + 1);
  const json strict = flow_json({"flow", "--json", "-", "--set", "feature_threshold=6121",
                                 sp.dir.path("prev.png"), sp.dir.path("next.png")});
  CHECK(strict["meancount"] == 0);  // no feature can reach 6121 (max 6120)
  CHECK(strict["quality"] == 0);
}

TEST_CASE("text summary and the backend list", "[cli][all-probes]") {
  ShiftedPair sp;
  const auto r = run_pxflow({"flow", sp.dir.path("prev.png"), sp.dir.path("next.png")});
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("x = +2.0000 px, y = -1.0000 px") != std::string::npos);
  CHECK(r.out.find("91,520 SAD ops") != std::string::npos);
  const auto list = run_pxflow({"backends"});
  REQUIRE(list.exit_code == 0);
  CHECK(list.out.find("ref-original   available") != std::string::npos);
  const auto help = run_pxflow({"flow", "--help"});
  CHECK(help.exit_code == 0);
  CHECK(help.out.find("--set") != std::string::npos);
  // Every command's help keeps its own footer (flow's forms, merge's exit codes), lists the
  // global options (the families' and --device-timeout), then the exit status, the environment
  // and its examples (the man pages' EXIT STATUS, ENVIRONMENT and EXAMPLES).
  CHECK(help.out.find("\nForms:\n") != std::string::npos);
  CHECK(run_pxflow({"merge", "--help"}).out.find("Exit 0: every shard") != std::string::npos);
  for (const std::string command : {"flow", "check", "bench", "report", "merge"}) {
    const auto h = run_pxflow({command, "--help"});
    INFO(command << " --help:\n" << h.out);
    const auto globals = h.out.find("Global options");
    const auto exit_status = h.out.find("\nExit status:\n  0  ");
    const auto environment = h.out.find("\nEnvironment:\n");
    const auto examples = h.out.find("\nExamples:\n  $ pxflow " + command + " ");
    CHECK(h.out.find("--device-timeout", globals) != std::string::npos);
    CHECK(globals < exit_status);
    CHECK(exit_status < environment);
    CHECK(environment < examples);
    CHECK(examples != std::string::npos);
    CHECK(h.out.find("  PXFLOW_OPENCV_MODULE  ", environment) < examples);
  }
  const auto top = run_pxflow({"--help"});
  CHECK(top.out.find("\nExit status:\n") != std::string::npos);
  CHECK(top.out.find("\nExamples:\n  $ pxflow flow ") != std::string::npos);
}

#ifdef PXFLOW_TEST_CPU_BUILT
// swar is compiled on every architecture, so the mask has a row to act on in every build.
TEST_CASE("disable-isa option masks CPU paths for one run", "[cli][cpu][all-probes]") {
  const auto list = run_pxflow({"backends"});
  REQUIRE(list.exit_code == 0);
  CHECK(list.out.find("swar           available") != std::string::npos);
  const auto masked = run_pxflow({"backends", "--disable-isa", "swar"});
  CHECK(masked.exit_code == 0);
  CHECK(masked.out.find("swar           skipped    masked by --disable-isa") != std::string::npos);
  const auto bad = run_pxflow({"backends", "--disable-isa", "mmx"});
  CHECK(bad.exit_code == 2);
  CHECK(bad.err_lines() == 1);
  CHECK(bad.err.find("unknown ISA 'mmx'") != std::string::npos);
}
#endif
