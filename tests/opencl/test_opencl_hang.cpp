// A kernel that never ends (tests/opencl/spin.cl, in place of opencl.cl's flow_item_per_poi)
// through the real backend: launch, flush, event polling up to --device-timeout x the work
// units, the line that says how long, for how much work and which option raises it; then the
// backend refuses work, and the process, whose device is abandoned with the kernel still
// running, ends at once. The spinning part runs in a child process (this binary, the hidden
// test below), so that how promptly such a process exits is measured too.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "build_paths.hpp"
#include "cl_program.hpp"
#include "device_wait.hpp"
#include "errors.hpp"
#include "grid.hpp"
#include "opencl_test_support.hpp"
#include "run_program.hpp"

using namespace pxflow;
using Catch::Matchers::Contains;

namespace {

constexpr const char* kChildTag = "[opencl-spin-child]";
constexpr double kTimeout = 0.25;

// 128x128 at S=31 (px4flow-64's other parameters), 2 pairs: the work the line must name.
Params hang_params() {
  Params p = profile("px4flow-64");
  p.width = p.height = 128;
  p.search_radius = 31;
  return p;
}

std::string self_path() {
  char buf[4096] = {};
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  return n > 0 ? std::string(buf, std::size_t(n)) : std::string();
}

std::shared_ptr<const cl::DeviceProgram> spin_program() {
  std::ifstream file(build_paths::opencl_spin_source, std::ios::binary);
  std::stringstream source;
  source << file.rdbuf();
  auto prog = std::make_shared<cl::DeviceProgram>();
  prog->device = cl::choose_device(cl::list_devices(), "");
  prog->context = cl::create_context(prog->device);
  prog->program = cl::build_program(prog->context.get(), prog->device, source.str());
  return prog;
}

}  // namespace

TEST_CASE("opencl: a spinning kernel (child process)", "[.][opencl-spin-child]") {
  device_timeout_seconds() = kTimeout;
  const Params p = hang_params();
  REQUIRE(poi_count(p) > 0);
  OpenclBackend backend({OpenclLayout::kItemPerPoi}, spin_program());
  std::vector<OwnedPair> owned = {random_pair(p.width, p.height, 31, 1),
                                  random_pair(p.width, p.height, 31, 2)};
  std::vector<FramePair> pairs;
  for (const auto& o : owned) pairs.push_back(o.view());
  std::vector<PoiRecord> out(pairs.size() * poi_count(p));
  OpCounts counts;
  for (const char* which : {"first: ", "second: "}) {
    try {
      backend.run(pairs, p, out, counts);
      FAIL("a kernel that never ends was reported finished");
    } catch (const BackendError& e) {
      std::cout << which << e.what() << "\n";
    }
  }
  CHECK(device_abandoned());
  std::cout << std::flush;
}  // the backend leaks its queue and buffers: nothing waits for the kernel

TEST_CASE("opencl: a kernel that never ends is given up after its allowance, then exits",
          "[opencl][hang]") {
  test::require_opencl_device();
  const Params p = hang_params();
  const DeviceWork work{2, poi_count(p), 31};
  double seconds = 0;
  // The guard only catches a child that never ends (one that waits for its spinning work at
  // exit): the work runs for months, so 600 s is no bound on how fast the child is.
  const auto r = test::run_program_within(self_path(), {kChildTag}, 600, seconds);
  INFO(r.out << r.err);
  INFO("the child took " << seconds << " s");  // shown, never bounded: slow is not hung
  REQUIRE(r.exit_code == 0);                   // -2: killed by the guard, the process hung
  CHECK_THAT(r.out, Contains("first: opencl on '") && Contains("': no result after ") &&
                        Contains(" s for " + work_text(work) +
                                 "; the device hangs or is slower than --device-timeout 0.25 "
                                 "allows per 1 M candidates: raise --device-timeout"));
  const std::size_t at = r.out.find("no result after ");
  REQUIRE(at != std::string::npos);
  const double waited = std::stod(r.out.substr(at + std::strlen("no result after ")));
  CHECK(waited >= work_units(work) * kTimeout - 0.05);  // it waited its whole allowance
  CHECK_THAT(r.out, Contains("second: opencl: device '") &&
                        Contains("unusable after an earlier failure: opencl on '"));
}
