// Device choice and error paths: a bad --device is one clear InputError, a problem beyond the
// device's limits is "unsupported" and a run of it throws without leaving partial records.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>

#include "errors.hpp"
#include "exactness.hpp"
#include "grid.hpp"
#include "opencl_test_support.hpp"
#include "registry.hpp"
#include "synthetic.hpp"

namespace pxflow::test {
namespace {

std::string message_of(const std::string& selector) {
  try {
    OpenclBackend backend({0, selector});
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError for device '" + selector + "'";
}

// The device list as the shared device rule (hosts/core/device_choice.hpp) prints it.
std::string known_devices() {
  std::string text;
  for (const auto& d : cl::list_devices())
    text += (text.empty() ? "" : ", ") + std::to_string(d.index) + " '" + d.name + "' (" +
            d.platform_name + ")";
  return " (devices: " + text + ")";
}

}  // namespace

// The rule and the text are the ones of tests/vulkan/test_vulkan_errors.cpp: one helper.
TEST_CASE("opencl: a device index out of range is a clear input error", "[opencl]") {
  require_opencl_device();
  const std::string index = std::to_string(cl::list_devices().size());
  CHECK(message_of(index) ==
        "opencl: device index " + index + " is out of range" + known_devices());
  // Any run of digits is an index, never a name: too many digits are out of range too.
  CHECK(message_of("12345678901234567890") ==
        "opencl: device index 12345678901234567890 is out of range" + known_devices());
}

TEST_CASE("opencl: a device name that matches nothing is a clear input error", "[opencl]") {
  require_opencl_device();
  CHECK(message_of("no-such-device-xyz") ==
        "opencl: no device name contains 'no-such-device-xyz'" + known_devices());
}

TEST_CASE("opencl: check and bench stop on a bad --device instead of skipping", "[opencl]") {
  require_opencl_device();
  for (const char* name : {"opencl", "opencl-item", "opencl-group"}) {
    INFO(name);
    CHECK_THROWS_AS(open_backend(find_backend(name), {0, "no-such-device-xyz"}), InputError);
  }
}

TEST_CASE("opencl: devices are chosen by index or case-insensitive name substring", "[opencl]") {
  require_opencl_device();
  const auto devices = cl::list_devices();
  const auto& last = devices.back();
  CHECK(OpenclBackend({0, std::to_string(last.index)}).device_name() == last.name);
  std::string upper = last.name.substr(0, std::min<std::size_t>(last.name.size(), 12));
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  CHECK(OpenclBackend({0, upper}).device_name().substr(0, upper.size()) ==
        devices.front().name.substr(0, upper.size()));
}

TEST_CASE("opencl: a pair beyond the buffer limit is unsupported and leaves no records",
          "[opencl]") {
  require_opencl_device();
  const Params p = profile("px4flow-64");
  OpenclBackend backend({}, {OpenclLayout::kGroupPerPoi, 0, 1000});  // < one 64x64 pair
  const std::string why = backend.unsupported(p);
  INFO(why);
  CHECK(why.find("exceeds the device's buffer limit") != std::string::npos);

  const OwnedPair pair = random_pair(64, 64, 4, 1);
  const FramePair view = pair.view();
  std::vector<PoiRecord> out = sentinel_records(poi_count(p));
  OpCounts counts;
  CHECK_THROWS_AS(backend.run({&view, 1}, p, out, counts), BackendError);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(out.data());
  CHECK(std::all_of(bytes, bytes + out.size() * sizeof(PoiRecord),
                    [](std::uint8_t b) { return b == 0; }));
}

TEST_CASE("opencl: a run reports its profiled device time", "[opencl]") {
  require_opencl_device();
  const Params p = profile("px4flow-64");
  const OwnedPair pair = random_pair(64, 64, 4, 2);
  const FramePair views[3] = {pair.view(), pair.view(), pair.view()};
  std::vector<PoiRecord> out(3 * poi_count(p));
  OpCounts counts;
  OpenclBackend backend({});
  backend.run(views, p, out, counts);
  CHECK(backend.last_timing().launches == 1);  // one launch for the whole batch
  CHECK(backend.last_timing().kernel_seconds > 0);
  backend.run({}, p, std::span<PoiRecord>{}, counts);  // an empty batch is a no-op
  CHECK(backend.last_timing().launches == 0);
}

}  // namespace pxflow::test
