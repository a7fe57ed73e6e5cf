// How long pxflow waits for a device before it calls it hung (docs/harness.md, "Waiting on a
// device"): one setting, --device-timeout SECONDS (alias --dut-timeout), and one rule shared by
// every family that waits on a device (the Vulkan fence, OpenCL events, the device-under-test
// link). A wait is allowed the timeout once per work unit it covers, so a large chunk on a busy
// CPU device is not taken for a hang, and a small test value still finds a true hang at once.
#pragma once
#include <chrono>
#include <cstdint>
#include <string>

#include "backend.hpp"

namespace pxflow {

// The work one wait covers: `pairs` frame pairs of `pois_per_pair` POIs at search radius S.
struct DeviceWork {
  std::uint64_t pairs = 0;
  std::uint64_t pois_per_pair = 0;
  int search_radius = 0;
  // Integer candidate positions searched: pairs x POIs x (2S+1)^2.
  std::uint64_t candidates() const;
};

// One work unit: a million candidate positions (about 64 M pixel differences).
inline constexpr double kCandidatesPerWorkUnit = 1e6;
// The default --device-timeout. The slowest correct kernel measured, lavapipe at S=31 on the
// 2-core machine under a load average of 5.5, took 3.2 s per 1 M candidates; 30 s leaves a
// ninefold margin (docs/harness.md, "Waiting on a device").
inline constexpr double kDefaultDeviceTimeout = 30.0;

// How long building one kernel may take: a driver's compile of a pipeline (lavapipe compiles at a
// pipeline's first dispatch, seconds at a large search radius with a cold shader cache on a busy
// machine). Build time, not device work: no --device-timeout applies, and a wait for a build
// notices a stop signal (docs/harness.md, "Waiting on a device"). 300 s, as for opening a backend.
inline constexpr double kBuildSeconds = 300;

// The --device-timeout in seconds (default kDefaultDeviceTimeout); set by the option, or by a
// test before it opens a device.
double& device_timeout_seconds();

// max(1, candidates / 1 M): how many times the timeout one wait for `work` may last.
double work_units(const DeviceWork& work);

// The allowance of one wait: device_timeout_seconds() x work_units(work).
std::chrono::duration<double> wait_allowance(const DeviceWork& work);

// "4 pairs (1,024 POIs at S=31)".
std::string work_text(const DeviceWork& work);

// "0.4", "30": a setting in seconds as a user writes it (%g), e.g. --device-timeout's value.
std::string setting_text(double seconds);

// The line of a wait that fired, after `who` ("vulkan", "opencl on 'cpu-...'"): "<who>: no result
// after 62.1 s for 4 pairs (1,024 POIs at S=31); the device hangs or is slower than
// --device-timeout 10 allows per 1 M candidates: raise --device-timeout".
std::string wait_failure_line(const std::string& who, double waited_seconds,
                              const DeviceWork& work);

// The hint that ends every wait failure: "the device hangs or is slower than --device-timeout 10
// allows[ per 1 M candidates]: raise --device-timeout" (`per_work`: the wait covered kernel work).
std::string raise_timeout_hint(bool per_work);

// The option, declared once by the CLI for every family: --device-timeout, alias --dut-timeout
// (recorded command lines carry the first name).
FamilyOption device_timeout_option();

// A device given up on while it may still run (a spinning shader or kernel): its queue and
// context are deliberately leaked, since destroying them would wait for the work forever. Noted
// here so that the process can end without waiting for the driver's threads.
void note_abandoned_device();
bool device_abandoned();

// Keeps a handle of an abandoned device (a queue, kernel or buffer given up unreleased) reachable
// for the rest of the process: deliberately leaked, so never reported as a leak by LeakSanitizer.
void keep_abandoned_handle(const void* handle);

// When a device was abandoned: flushes stdout and stderr and ends the process now with `code`
// (std::_Exit: no static destructor or atexit handler of a driver may join a spinning thread).
// Returns otherwise.
void exit_now_if_device_abandoned(int code);

}  // namespace pxflow
