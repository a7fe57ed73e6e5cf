// Device selection, limits and failure paths: a --device that names nothing is one clear
// InputError, a driver limit one clear BackendError, no crash, no records written when a run is
// refused.
#include <algorithm>
#include <catch2/catch.hpp>
#include <string>

#include "errors.hpp"
#include "exactness.hpp"
#include "grid.hpp"
#include "registry.hpp"
#include "vulkan/batch_plan.hpp"
#include "vulkan/device_select.hpp"
#include "vulkan_test_util.hpp"

using namespace pxflow;
using namespace pxflow::test;
using Catch::Matchers::Contains;
using Catch::Matchers::Message;

namespace {

std::vector<vk::DeviceCandidate> fake_devices() {
  return {{"llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU, ""},
          {"Old GPU", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, "Vulkan 1.1 < 1.2"},
          {"Intel(R) UHD Graphics", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, ""},
          {"AMD Radeon RX", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, ""}};
}

}  // namespace

TEST_CASE("vulkan: device selection prefers GPUs, honours index and name", "[vulkan]") {
  auto d = fake_devices();
  CHECK(vk::select_device(d, "") == 3);
  CHECK(vk::select_device(d, "0") == 0);
  CHECK(vk::select_device(d, "uhd") == 2);
  CHECK(vk::select_device(d, "LLVMPIPE") == 0);
  CHECK(vk::select_device(d, "E") == 0);  // in names 0, 2 and 3: the first one wins
  d.pop_back();
  CHECK(vk::select_device(d, "") == 2);  // the unusable discrete GPU is passed over
  d.pop_back();
  CHECK(vk::select_device(d, "") == 0);
  CHECK_THROWS_WITH(vk::select_device({}, ""), Contains("no Vulkan device found"));
}

// The rule and the text are the ones of tests/opencl/test_opencl_errors.cpp (one helper,
// hosts/core/device_choice.hpp): an index must exist, a name must match; both are InputErrors
// that list the devices.
TEST_CASE("vulkan: a --device that names no device is the shared input error", "[vulkan]") {
  const auto d = fake_devices();
  const std::string known =
      " (devices: 0 'llvmpipe (LLVM 15.0.6, 256 bits)' (cpu), 1 'Old GPU' (discrete gpu), "
      "2 'Intel(R) UHD Graphics' (integrated gpu), 3 'AMD Radeon RX' (discrete gpu))";
  CHECK_THROWS_MATCHES(vk::select_device(d, "4"), InputError,
                       Message("vulkan: device index 4 is out of range" + known));
  CHECK_THROWS_MATCHES(
      vk::select_device(d, "12345678901234567890"), InputError,
      Message("vulkan: device index 12345678901234567890 is out of range" + known));
  CHECK_THROWS_MATCHES(vk::select_device(d, "nvidia"), InputError,
                       Message("vulkan: no device name contains 'nvidia'" + known));
  // A device that exists but cannot run the kernel is the driver's limit: a BackendError.
  CHECK_THROWS_MATCHES(
      vk::select_device(d, "1"), BackendError,
      Message("vulkan: device '1' (Old GPU) cannot run the kernel: Vulkan 1.1 < 1.2"));
}

TEST_CASE("vulkan: a bad --device gives one clear error", "[vulkan]") {
  const BackendRow& row = find_backend("vulkan");
  REQUIRE(row.probe() == "");
  CHECK_THROWS_WITH(row.create({.threads = 0, .device = "99"}),
                    Contains("vulkan: device index 99 is out of range"));
  // A device that names nothing is the user's input (exit 2 in the CLI), as for OpenCL.
  CHECK_THROWS_AS(row.create({.threads = 0, .device = "99"}), InputError);
  CHECK_THROWS_AS(row.create({.threads = 0, .device = "no-such-device"}), InputError);
  // check and bench open rows through open_backend: a bad --device is an error there, not a skip.
  CHECK_THROWS_AS(open_backend(row, {.threads = 0, .device = "99"}), InputError);
  CHECK(row.create({.threads = 0, .device = "0"}) != nullptr);
  CHECK(row.create({.threads = 0, .device = "llvmpipe"}) != nullptr);
}

TEST_CASE("vulkan: chunks respect the buffer limit", "[vulkan]") {
  const Params p = make_params("px4flow-64", 64, 64);
  const vk::BatchLayout layout = vk::batch_layout(p);
  CHECK(layout.words_per_frame == 64 * 64 / 4 + 1);
  CHECK(vk::pairs_per_chunk(layout, {layout.pair_bytes * 3 + 1, ~0ull}) == 3);
  CHECK(vk::pairs_per_chunk(layout, {layout.pair_bytes - 1, ~0ull}) == 0);
  CHECK(vk::pairs_per_chunk(layout, {~0ull >> 8, layout.work_per_pair * 2}) == 2);
  CHECK(vk::pairs_per_chunk(layout, {~0ull >> 8, 1}) == 1);  // never 0 for work alone

  VulkanConfig config;
  config.max_buffer_bytes = layout.pair_bytes * 3;
  config.max_groups_per_dispatch = 1;  // 64 POIs per dispatch at local size 64
  auto vk = make_vulkan(config);
  expect_exact(*vk, random_pairs(64, 64, 4, 10, 77), p);
  CHECK(vk->last_chunks() == 4);
  CHECK(vk->last_dispatches() == 10);
  REQUIRE(vk->last_device_seconds().has_value());
  CHECK(*vk->last_device_seconds() > 0.0);
}

TEST_CASE("vulkan: a frame pair beyond the buffer limit is refused untouched", "[vulkan]") {
  VulkanConfig config;
  config.max_buffer_bytes = 4096;
  auto vk = make_vulkan(config);
  const Params p = make_params("px4flow-64", 64, 64);
  CHECK_THAT(vk->unsupported(p), Contains("bytes in one storage buffer"));
  const OwnedPair pair = random_pair(64, 64, 4, 1);
  const FramePair view = pair.view();
  std::vector<PoiRecord> out = sentinel_records(64);
  OpCounts counts;
  CHECK_THROWS_AS(vk->run({&view, 1}, p, out, counts), BackendError);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(out.data());
  CHECK(std::all_of(bytes, bytes + out.size() * sizeof(PoiRecord),
                    [](std::uint8_t b) { return b == kUnwrittenSentinel; }));
  CHECK(make_vulkan()->unsupported(p).empty());
}

TEST_CASE("vulkan: a dispatch past the records hits the guard after them", "[vulkan]") {
  // The guard zones (hosts/core/guard_zone.hpp): one item more than the output, written by the
  // real shader into the guard, is the backend's failure; the same run without it passes.
  const Params p = make_params("px4flow-64", 64, 64);
  const OwnedPair pair = random_pair(64, 64, 4, 3);
  const FramePair view = pair.view();
  std::vector<PoiRecord> out(poi_count(p));
  OpCounts counts;
  CHECK_NOTHROW(make_vulkan()->run({&view, 1}, p, out, counts));
  VulkanConfig config;
  config.overrun_items = 1;
  auto vk = make_vulkan(config);
  CHECK_THROWS_WITH(vk->run({&view, 1}, p, out, counts),
                    Contains("vulkan: wrote past its output (") && Contains(" after record 63)"));
}
