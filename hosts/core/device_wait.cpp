#include "device_wait.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "counted.hpp"
#include "errors.hpp"

namespace pxflow {
namespace {

std::atomic<bool> g_abandoned{false};

std::string seconds_text(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, seconds < 1 ? "%.2f s" : "%.1f s", seconds);
  return buf;
}

}  // namespace

std::uint64_t DeviceWork::candidates() const {
  const std::uint64_t side = 2 * static_cast<std::uint64_t>(std::max(search_radius, 0)) + 1;
  return pairs * pois_per_pair * side * side;
}

double& device_timeout_seconds() {
  static double seconds = kDefaultDeviceTimeout;
  return seconds;
}

double work_units(const DeviceWork& work) {
  return std::max(1.0, static_cast<double>(work.candidates()) / kCandidatesPerWorkUnit);
}

std::chrono::duration<double> wait_allowance(const DeviceWork& work) {
  return std::chrono::duration<double>(device_timeout_seconds() * work_units(work));
}

std::string work_text(const DeviceWork& work) {
  return grouped(work.pairs) + (work.pairs == 1 ? " pair (" : " pairs (") +
         grouped(work.pairs * work.pois_per_pair) +
         " POIs at S=" + std::to_string(work.search_radius) + ")";
}

std::string setting_text(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", seconds);
  return buf;
}

std::string raise_timeout_hint(bool per_work) {
  return "the device hangs or is slower than --device-timeout " +
         setting_text(device_timeout_seconds()) + " allows" +
         (per_work ? " per 1 M candidates" : "") + ": raise --device-timeout";
}

std::string wait_failure_line(const std::string& who, double waited_seconds,
                              const DeviceWork& work) {
  return who + ": no result after " + seconds_text(waited_seconds) + " for " + work_text(work) +
         "; " + raise_timeout_hint(true);
}

FamilyOption device_timeout_option() {
  FamilyOption o;
  o.flag = "--device-timeout,--dut-timeout";
  o.value_name = "SECONDS";
  o.help =
      "Seconds a device (Vulkan, OpenCL, --dut, m4-qemu) may take per 1 M candidate positions "
      "(POIs x (2S+1)^2) before it is called hung; every wait is allowed at least this once "
      "(default 30; --dut-timeout is the same option); docs/harness.md";
  o.apply = [](const std::string& text) {
    char* end = nullptr;
    const double s = std::strtod(text.c_str(), &end);
    if (text.empty() || *end || !(s >= 0.01 && s <= 3600))
      throw InputError("--device-timeout: '" + text +
                       "': allowed seconds from 0.01 to 3600 (see pxflow --help)");
    device_timeout_seconds() = s;
  };
  return o;
}

void note_abandoned_device() { g_abandoned = true; }

bool device_abandoned() { return g_abandoned; }

void keep_abandoned_handle(const void* handle) {
  // Never freed: a global pointer keeps every handle reachable until the process ends.
  static auto* const kept = new std::vector<const void*>;
  kept->push_back(handle);
}

void exit_now_if_device_abandoned(int code) {
  if (!g_abandoned) return;
  std::fflush(stdout);
  std::fflush(stderr);
  std::_Exit(code);
}

}  // namespace pxflow
