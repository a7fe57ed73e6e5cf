// The one rule of every wait on a device (hosts/core/device_wait.hpp): the allowance is
// --device-timeout once per million candidate positions (pairs x POIs x (2S+1)^2), never less
// than once; and the line a wait that fired prints.
#include <catch2/catch.hpp>

#include "device_wait.hpp"

using namespace pxflow;

TEST_CASE("the wait allowance scales with pairs, POIs and S", "[unit][device-wait]") {
  device_timeout_seconds() = 2;
  CHECK(DeviceWork{4, 256, 31}.candidates() == 4u * 256 * 63 * 63);
  CHECK(work_units({1, 1, 0}) == 1.0);  // at least one unit
  CHECK(wait_allowance({1, 64, 4}).count() == 2.0);
  CHECK(wait_allowance({10, 1000, 49}).count() == Approx(2 * 10 * 1000 * 99 * 99 / 1e6));
  CHECK(wait_allowance({20, 1000, 49}).count() ==
        Approx(2 * wait_allowance({10, 1000, 49}).count()));
  CHECK(wait_allowance({10, 2000, 49}).count() ==
        Approx(2 * wait_allowance({10, 1000, 49}).count()));
  CHECK(wait_allowance({10, 1000, 99}).count() > 3.9 * wait_allowance({10, 1000, 49}).count());
  CHECK(work_text({4, 256, 31}) == "4 pairs (1,024 POIs at S=31)");
  CHECK(work_text({1, 1234567, 7}) == "1 pair (1,234,567 POIs at S=7)");
  CHECK(wait_failure_line("vulkan", 62.14, {4, 256, 31}) ==
        "vulkan: no result after 62.1 s for 4 pairs (1,024 POIs at S=31); the device hangs or is "
        "slower than --device-timeout 2 allows per 1 M candidates: raise --device-timeout");
  device_timeout_seconds() = kDefaultDeviceTimeout;  // as the other tests expect
}
