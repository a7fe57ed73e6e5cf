// A shader that never ends (tests/vulkan/spin.comp) through the real CommandRunner and its wait:
// the wait fires after --device-timeout x the work units it was given, with the line that says
// how long, for how much work and which option raises it; the runner then refuses work, and the
// process, whose device is abandoned with the shader still spinning, ends at once. The spinning
// part runs in a child process (this binary, the hidden test below), so that how promptly a
// process with an abandoned device exits is measured too.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstring>
#include <iostream>

#include "device_wait.hpp"
#include "errors.hpp"
#include "run_program.hpp"
#include "spin_pipeline.hpp"
#include "vulkan/command_runner.hpp"
#include "vulkan/host_buffer.hpp"

using namespace pxflow;
using Catch::Matchers::Contains;

namespace {

constexpr const char* kChildTag = "[vulkan-spin-child]";
// 4 pairs x 256 POIs x 63^2 candidates = 4.06 work units: the wait is allowed 4.06 x 0.25 s.
const DeviceWork kWork{4, 256, 31};
constexpr double kTimeout = 0.25;
constexpr const char* kLineTail =
    " s for 4 pairs (1,024 POIs at S=31); the device hangs or is slower than --device-timeout "
    "0.25 allows per 1 M candidates: raise --device-timeout";

std::string self_path() {
  char buf[4096] = {};
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  return n > 0 ? std::string(buf, std::size_t(n)) : std::string();
}

}  // namespace

TEST_CASE("vulkan: a spinning shader (child process)", "[.][vulkan-spin-child]") {
  device_timeout_seconds() = kTimeout;
  vk::Context ctx({});
  vk::HostBuffer flag(ctx, 256);
  std::memset(flag.data(), 0, 256);  // `stop` stays 0: the shader never ends
  test::SpinPipeline spin(ctx, flag.buffer());
  vk::CommandRunner runner(ctx);
  const auto body = [&](VkCommandBuffer cmd) { spin.record(cmd); };
  try {
    runner.run(body, kWork);
    const auto* w = reinterpret_cast<const std::uint32_t*>(flag.data());
    FAIL("a shader that never ends was reported finished (stop " << w[0] << ", count " << w[1]
                                                                 << ")");
  } catch (const BackendError& e) {
    std::cout << "first: " << e.what() << "\n";
  }
  try {
    runner.run(body, kWork);
  } catch (const BackendError& e) {
    std::cout << "second: " << e.what() << "\n";
  }
  CHECK(ctx.abandoned());
  CHECK(device_abandoned());
  std::cout << std::flush;
}  // the runner, pipeline, buffer and context leak themselves: nothing waits for the shader

TEST_CASE("vulkan: a shader that never ends is given up after its allowance, then exits",
          "[vulkan][hang]") {
  double seconds = 0;
  // The guard only catches a child that never ends (one that waits for its spinning work at
  // exit): the work runs for months, so 600 s is no bound on how fast the child is.
  const auto r = test::run_program_within(self_path(), {kChildTag}, 600, seconds);
  INFO(r.out << r.err);
  INFO("the child took " << seconds << " s");  // shown, never bounded: slow is not hung
  REQUIRE(r.exit_code == 0);                   // -2: killed by the guard, the process hung
  CHECK_THAT(r.out, Contains("first: vulkan: no result after ") && Contains(kLineTail));
  const std::size_t at = r.out.find("no result after ");
  REQUIRE(at != std::string::npos);
  const double waited = std::stod(r.out.substr(at + std::strlen("no result after ")));
  CHECK(waited >= work_units(kWork) * kTimeout - 0.05);  // it waited its whole allowance
  CHECK_THAT(r.out, Contains("second: vulkan: device unusable after an earlier failure"));
}
