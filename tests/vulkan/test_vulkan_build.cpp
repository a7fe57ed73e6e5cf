// Building a pipeline is build time, never part of a wait on the device (docs/vulkan.md, "Building
// a pipeline"). lavapipe compiles a pipeline at its first dispatch: with Mesa's shader cache cold
// that is seconds at a large radius, and it used to run inside the first chunk's fence wait, whose
// allowance is sized by the chunk's work; a cold-cache `pxflow check --backends vulkan` on a busy
// machine failed at S = 28-29 ("no result after 30.0 s"). Here the cache is off, the allowance
// cut to 0.1 s per work unit, far below the compile of S = 12, and the run must still pass, with
// the compile counted as the backend's build time.
#include <catch2/catch.hpp>

#include "device_wait.hpp"
#include "grid.hpp"
#include "scoped_env.hpp"
#include "vulkan_test_util.hpp"

using namespace pxflow;
using namespace pxflow::test;

namespace {

constexpr double kTinyTimeout = 0.1;

struct ScopedDeviceTimeout {
  explicit ScopedDeviceTimeout(double s) { device_timeout_seconds() = s; }
  ~ScopedDeviceTimeout() { device_timeout_seconds() = kDefaultDeviceTimeout; }
};

// A backend whose device has no shader cache: Mesa reads the variable when the device is made.
std::unique_ptr<VulkanBackend> cold_vulkan() {
  const ScopedEnv no_cache("MESA_SHADER_CACHE_DISABLE", "true");
  return make_vulkan();
}

}  // namespace

TEST_CASE("vulkan: a pipeline's compile is build time and never part of a device wait",
          "[vulkan]") {
  auto vk = cold_vulkan();
  const double before = vk->build_seconds();  // the constructor's pipelines, at S = 4
  const ScopedDeviceTimeout tiny(kTinyTimeout);
  // One POI at S = 12: 625 candidates, well under a millisecond of work, but a compile of about
  // a second (25 s at S = 31 on a busy machine: too long for a test).
  const Params p = make_params("px4flow-64", 35, 35, 12, 1);
  const double allowance = kTinyTimeout * work_units(DeviceWork{1, poi_count(p), 12});
  SECTION("run() builds and warms its pipelines itself") {
    expect_exact(*vk, random_pairs(p.width, p.height, p.search_radius, 1), p);
  }
  SECTION("prepare() builds them before run()") {
    vk->prepare(p);
    const double built = vk->build_seconds();
    expect_exact(*vk, random_pairs(p.width, p.height, p.search_radius, 1), p);
    CHECK(vk->build_seconds() == built);  // run() built nothing more
  }
  // The compile took longer than the whole allowance of the run's wait: the test did put it
  // where a wait sized by the work would have failed.
  const double built = vk->build_seconds() - before;
  INFO("building S = 12 took " << built << " s; the wait's allowance: " << allowance << " s");
  CHECK(built > allowance);
}
