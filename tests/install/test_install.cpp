// The installed tree as a user meets it: `cmake --install` of this build into a temporary
// prefix; the installed pxflow, gap8-run, man pages and package files; and a consumer program
// (consumer/) built against that prefix only, once with find_package(pxflow) and once with
// pkg-config, whose records on a real pair must equal the installed `pxflow flow --json`.
#include <catch2/catch.hpp>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "build_paths.hpp"
#include "run_program.hpp"
#include "sample_data.hpp"

using nlohmann::json;
using pxflow::test::run_program;
using pxflow::test::RunResult;
using pxflow::test::slurp;
namespace fs = std::filesystem;

namespace {

RunResult must_run(const std::string& binary, const std::vector<std::string>& args) {
  RunResult r = run_program(binary, args);
  std::string line = binary;
  for (const auto& a : args) line += " " + a;
  INFO("command: " << line << "\nstdout: " << r.out << "\nstderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  return r;
}

// `pxflow flow` with its JSON on stdout: `--json` when it is a flag, `--json -` when it takes a
// file (issue 15's shared convention), as `pxflow flow --help` says.
json flow_json(const std::string& pxflow, std::vector<std::string> args) {
  const std::string help = must_run(pxflow, {"flow", "--help"}).out;
  const bool takes_file = std::regex_search(help, std::regex("\\n +--json [A-Z]"));
  if (takes_file) args.insert(args.begin(), "-");
  args.insert(args.begin(), {"flow", "--json"});
  const RunResult r = must_run(pxflow, args);
  return json::parse(r.out);
}

// The subcommands `pxflow --help` lists (the lines of its "Subcommands:" section).
std::vector<std::string> subcommands(const std::string& help) {
  std::vector<std::string> names;
  const auto start = help.find("\nSubcommands:\n");
  REQUIRE(start != std::string::npos);
  std::istringstream lines(help.substr(start + 14));
  const std::regex entry("^  ([a-z0-9][a-z0-9-]*)( .*)?$");
  for (std::string line; std::getline(lines, line) && !line.empty();) {
    std::smatch m;
    if (std::regex_match(line, m, entry)) names.push_back(m[1]);
  }
  return names;
}

// An 8-bit image as raw gray bytes, converted as pxflow's loader does (hosts/io: OpenCV's
// BGR(A)-to-gray weights); the test proves it by comparing pxflow flow on both. Returns "WxH".
std::string write_raw(const std::string& image, const std::string& raw) {
  const cv::Mat img = cv::imread(image, cv::IMREAD_UNCHANGED);
  REQUIRE(!img.empty());
  REQUIRE(img.depth() == CV_8U);
  cv::Mat gray = img;
  if (img.channels() == 3) cv::cvtColor(img, gray, cv::COLOR_BGR2GRAY);
  if (img.channels() == 4) cv::cvtColor(img, gray, cv::COLOR_BGRA2GRAY);
  REQUIRE(gray.channels() == 1);
  std::ofstream out(raw, std::ios::binary);
  for (int y = 0; y < gray.rows; ++y) out.write(gray.ptr<char>(y), gray.cols);
  REQUIRE(out.good());
  return std::to_string(gray.cols) + "x" + std::to_string(gray.rows);
}

// The same answer: the float bits, the quality, the accepted count, and every record field by
// field (SPEC §4's fields; pxflow may print more keys per record, such as a status name).
void require_same_answer(const json& a, const json& b) {
  for (const char* key : {"flow_x_bits", "flow_y_bits", "quality", "meancount"}) {
    CAPTURE(key);
    REQUIRE(a.at(key) == b.at(key));
  }
  const json& pa = a.at("pois");
  const json& pb = b.at("pois");
  REQUIRE(pa.size() == pb.size());
  for (std::size_t i = 0; i < pa.size(); ++i)
    for (const char* field :
         {"x", "y", "status", "feature", "dx", "dy", "sad", "dir", "sub", "hx", "hy"}) {
      CAPTURE(i, field);
      REQUIRE(pa[i].at(field) == pb[i].at(field));
    }
}

// The backends --json row NAME. `backends` probes every row, Vulkan included, whose lavapipe
// driver leaks inside itself: the leak check is off for this command only
// (tests/cli/CMakeLists.txt).
json backend_row(const std::string& pxflow, const std::string& name) {
  const json list =
      json::parse(must_run("/usr/bin/env", {"ASAN_OPTIONS=detect_leaks=0:abort_on_error=1", pxflow,
                                            "backends", "--json", "-"})
                      .out);
  for (const json& row : list.at("backends"))
    if (row.at("backend") == name) return row;
  FAIL("no row " << name << " in pxflow backends");
  return {};
}

// Does `file` contain `text` anywhere (a binary's bytes included)?
bool file_contains(const std::string& file, const std::string& text) {
  const std::string bytes = slurp(file);
  REQUIRE(!bytes.empty());
  return bytes.find(text) != std::string::npos;
}

// The installed tree with the build tree out of its reach: the prefix moved elsewhere, PATH
// without the build folder. Everything pxflow runs or loads beside itself (the OpenCV module,
// the Cortex-M4 firmware, the reference device) is found from the moved binary's own place.
void check_moved_prefix(const std::string& moved, const json& expected_flow,
                        const std::string& png1, const std::string& png2) {
  const std::string pxflow = moved + "/bin/pxflow";
  // The OpenCV module: decoding PNGs loads it from <moved>/lib/.../pxflow.
  require_same_answer(flow_json(pxflow, {png1, png2}), expected_flow);
  if (PXFLOW_HAS_DUT_REF) {
    // The README's --dut example as an installed tree runs it, the device found in PATH; exit 0
    // with --require ref: the row ran and every record matched.
    must_run("/usr/bin/env", {"PATH=" + moved + "/bin:/usr/bin:/bin", pxflow, "check", "--backends",
                              "ref-original,ref", "--dut", "ref=exec:pxflow-dut-ref", "--require",
                              "ref", "--cases", "4"});
  }
  if (PXFLOW_HAS_M4_FIRMWARE) {
    const json row = backend_row(pxflow, "m4-qemu");
    CAPTURE(row.dump());
    if (fs::exists("/usr/bin/qemu-system-arm")) {
      CHECK(row.at("available") == true);  // the probe found the firmware and QEMU answered
    } else {
      WARN("no qemu-system-arm: only the firmware's lookup was checked");
      CHECK(row.at("reason").get<std::string>().find("qemu-system-arm") != std::string::npos);
    }
  }
}

// The build's own pxflow copied alone into `dir`, as a build folder that was moved away leaves
// it: what it cannot find is said by name and where it looked, never by a build-tree path.
void check_binary_alone(const std::string& dir, const std::string& png1, const std::string& png2) {
  fs::create_directories(dir);
  const std::string alone = dir + "/pxflow";
  const std::string real_dir = fs::canonical(dir);  // as /proc/self/exe names it
  fs::copy_file(build_paths::pxflow, alone);
  if (PXFLOW_HAS_M4_FIRMWARE && fs::exists("/usr/bin/qemu-system-arm")) {
    const std::string reason = backend_row(alone, "m4-qemu").at("reason");
    CAPTURE(reason);
    CHECK(reason.find("firmware not built or not installed: no pxflow_m4_dut.elf at " + real_dir) !=
          std::string::npos);
    CHECK(reason.find(build_paths::build_dir) == std::string::npos);
  }
  const RunResult no_module = run_program(alone, {"flow", png1, png2});
  CAPTURE(no_module.err);
  CHECK(no_module.exit_code == 2);
  CHECK(no_module.err_lines() == 1);
  CHECK(no_module.err.find("the OpenCV module") != std::string::npos);
  CHECK(no_module.err.find(build_paths::build_dir) == std::string::npos);
}

}  // namespace

TEST_CASE("the installed tree runs, and a consumer built against it alone matches pxflow flow",
          "[install]") {
  pxflow::test::TempDir tmp;
  const std::string prefix = tmp.path("prefix");
  const std::string libdir = prefix + "/" + PXFLOW_LIBDIR;
  must_run(build_paths::cmake, {"--install", build_paths::build_dir, "--prefix", prefix});

  const std::string pxflow = prefix + "/bin/pxflow";
  for (const std::string& file :
       {pxflow, prefix + "/include/pxflow/registry.hpp", prefix + "/include/pxflow/backend.hpp",
        prefix + "/include/pxflow/params.hpp", prefix + "/include/pxflow/frame.hpp",
        prefix + "/include/pxflow/record.hpp", libdir + "/libpxflow_core.a",
        libdir + "/libpxflow_reference.a", libdir + "/cmake/pxflow/pxflowConfig.cmake",
        libdir + "/cmake/pxflow/pxflowConfigVersion.cmake",
        libdir + "/cmake/pxflow/pxflowTargets.cmake", libdir + "/pkgconfig/pxflow.pc"}) {
    CAPTURE(file);
    CHECK(fs::is_regular_file(file));
  }
  if (PXFLOW_HAS_DUT_REF) CHECK(fs::is_regular_file(prefix + "/bin/pxflow-dut-ref"));
  if (PXFLOW_HAS_M4_FIRMWARE)
    CHECK(fs::is_regular_file(prefix + "/" PXFLOW_DATADIR "/pxflow/pxflow_m4_dut.elf"));
  if (PXFLOW_HAS_GAP8_RUN) {
    CHECK(fs::is_regular_file(prefix + "/bin/gap8-run"));
    // It starts (its libelf resolves) and is the runner: no ELF is exit 2 with its usage.
    const RunResult runner = run_program(prefix + "/bin/gap8-run", {});
    CHECK(runner.exit_code == 2);
    CHECK(runner.err.find("usage: gap8-run") != std::string::npos);
  }

  // Nothing installed points back into the build or the source tree.
  const std::string source_dir =
      fs::path(build_paths::install_consumer_dir).parent_path().parent_path().parent_path();
  for (const std::string& file :
       {libdir + "/cmake/pxflow/pxflowTargets.cmake", libdir + "/cmake/pxflow/pxflowConfig.cmake",
        libdir + "/pkgconfig/pxflow.pc"}) {
    CAPTURE(file);
    const std::string text = slurp(file);
    REQUIRE(!text.empty());
    CHECK(text.find(build_paths::build_dir) == std::string::npos);
    CHECK(text.find(source_dir + "/") == std::string::npos);
  }
  // Nor does any program installed: no path of the build tree is compiled in, so none can be
  // opened (what they load is found relative to the binary: hosts/core/own_files.hpp). A build
  // with debug info or sanitizers records where its sources were compiled (DWARF, the
  // sanitizers' reports), the build tree among them, with no lookup behind it: there the moved
  // prefix below is the evidence.
  if (PXFLOW_RECORDS_SOURCE_PATHS) {
    WARN("debug info or sanitizers: the installed programs were not scanned for the build path");
  } else {
    for (const auto& entry : fs::recursive_directory_iterator(prefix)) {
      const bool program =
          (entry.status().permissions() & fs::perms::owner_exec) != fs::perms::none;
      const bool module = entry.path().extension() == ".so";
      if (!entry.is_regular_file() || !(program || module)) continue;
      CAPTURE(entry.path());
      CHECK_FALSE(file_contains(entry.path(), build_paths::build_dir));
    }
  }

  // The installed binary is this build's: the same --version line (commit, compiler, families).
  const RunResult version = must_run(pxflow, {"--version"});
  CHECK(version.out.rfind("pxflow ", 0) == 0);
  CHECK(version.out == must_run(build_paths::pxflow, {"--version"}).out);

  // The man pages: pxflow.1 and one page per subcommand of --help, named in pxflow.1.
  if (PXFLOW_HAS_MAN_PAGES) {
    const std::string man1 = prefix + "/" + PXFLOW_MANDIR + "/man1/";
    const std::string main_page = slurp(man1 + "pxflow.1");
    REQUIRE(main_page.find(".TH PXFLOW \"1\"") != std::string::npos);
    const auto names = subcommands(must_run(pxflow, {"--help"}).out);
    REQUIRE(names.size() >= 6);
    for (const auto& name : names) {
      CAPTURE(name);
      std::string upper = name;
      for (auto& c : upper) c = static_cast<char>(std::toupper(c));
      const std::string page = slurp(man1 + "pxflow-" + name + ".1");
      CHECK(page.find(".TH PXFLOW-" + upper + " \"1\"") != std::string::npos);
      // Each command's page lists the global options, then the sections every page has.
      const auto globals = page.find(".SS \"Global options");
      CHECK(page.find("\\-\\-device\\-timeout", globals) != std::string::npos);
      CHECK(globals < page.find(".SH \"EXIT STATUS\""));
      CHECK(page.find(".SH ENVIRONMENT\n") != std::string::npos);
      CHECK(page.find("PXFLOW_OPENCV_MODULE") != std::string::npos);
      CHECK(page.find(".SH EXAMPLES\n") != std::string::npos);
      CHECK(main_page.find(".BR pxflow\\-" + name + " (1)") != std::string::npos);
    }
    if (fs::exists("/usr/bin/man")) {
      const RunResult shown = must_run("/usr/bin/man", {"-P", "cat", "-l", man1 + "pxflow.1"});
      CHECK(shown.out.find("PXFLOW(1)") != std::string::npos);
      CHECK(shown.out.find("pxflow-flow(1)") != std::string::npos);
      for (const char* section : {"\nEXIT STATUS\n", "\nENVIRONMENT\n", "\nEXAMPLES\n"})
        CHECK(shown.out.find(section) != std::string::npos);
      CHECK(shown.out.find(version.out.substr(0, version.out.find(' ', 7))) !=
            std::string::npos);  // the footer: "pxflow 0.1"
    } else {
      WARN("no /usr/bin/man (man-db): the pages were checked as files only");
    }
  } else {
    WARN("PXFLOW_MAN_PAGES=OFF: no man pages to check");
  }

  // A real pair, also as raw frames (the consumer reads raw frames only: it needs no OpenCV).
  const std::string data = pxflow::kSampleDataDir;
  const std::string png1 = data + "/rubberwhale1.png", png2 = data + "/rubberwhale2.png";
  const std::string size = write_raw(png1, tmp.path("prev.raw"));
  REQUIRE(write_raw(png2, tmp.path("next.raw")) == size);

  // The consumer, with CMake: find_package(pxflow) from the prefix and nowhere else.
  const std::string cmake_build = tmp.path("consumer-cmake");
  must_run(build_paths::cmake,
           {"-S", build_paths::install_consumer_dir, "-B", cmake_build,
            "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_CXX_COMPILER=" PXFLOW_CXX,
            "-DCMAKE_PREFIX_PATH=" + prefix, "-DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF"});
  CHECK(slurp(cmake_build + "/CMakeCache.txt")
            .find("pxflow_DIR:PATH=" + libdir + "/cmake/pxflow\n") != std::string::npos);
  must_run(build_paths::cmake, {"--build", cmake_build});

  // The consumer, with pkg-config: one compiler line, as the README shows it.
  const std::string pc_binary = tmp.path("consumer-pkg-config");
  must_run("/bin/sh",
           {"-c", "PKG_CONFIG_PATH='" + libdir + "/pkgconfig' && export PKG_CONFIG_PATH && '" +
                      PXFLOW_CXX + "' -std=c++20 -O2 '" + build_paths::install_consumer_dir +
                      "/consumer.cpp' -o '" + pc_binary + "' $('" + PXFLOW_PKG_CONFIG +
                      "' --cflags --libs pxflow)"});

  // Both answer with the registry's default backend; pxflow flow runs the same backend on the
  // PNG files, and ref-original on the raw ones (the raw frames are the PNGs' pixels).
  const json from_png_ref = flow_json(pxflow, {png1, png2});
  const json from_raw_ref =
      flow_json(pxflow, {"--size", size, tmp.path("prev.raw"), tmp.path("next.raw")});
  require_same_answer(from_png_ref, from_raw_ref);
  std::size_t accepted = 0;
  for (const auto& poi : from_png_ref.at("pois")) accepted += poi.at("status") == 2;
  CHECK(from_png_ref.at("pois").size() == 64);  // px4flow-64: 8x8 POIs
  CHECK(accepted >= 10);  // a real estimate: MINCOUNT (10) accepted POIs or more

  for (const std::string& consumer : {cmake_build + "/consumer", pc_binary}) {
    CAPTURE(consumer);
    const RunResult r = must_run(consumer, {tmp.path("prev.raw"), tmp.path("next.raw"), size});
    const json mine = json::parse(r.out);
    const std::string backend = mine.at("backend");
    CAPTURE(backend);
    require_same_answer(mine, flow_json(pxflow, {"--backend", backend, png1, png2}));
    require_same_answer(mine, from_png_ref);
  }

  const std::string moved = tmp.path("moved");
  fs::rename(prefix, moved);
  check_moved_prefix(moved, from_png_ref, png1, png2);
  check_binary_alone(tmp.path("alone"), png1, png2);
}
