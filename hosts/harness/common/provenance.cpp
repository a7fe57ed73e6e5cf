#include "provenance.hpp"

#include <sys/utsname.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string_view>
#include <thread>

#include "pxflow_version.h"
#include "system_files.hpp"

namespace pxflow {
namespace {

// The value of the first line of `path` that starts with `key` ("key : value", "KEY=value").
std::string first_value_of(const std::string& path, const std::string& key) {
  std::istringstream in(read_system_file(path));
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key, 0) == 0) {
      auto v = line.substr(line.find_first_of(":=") + 1);
      v.erase(0, v.find_first_not_of(" \t\""));
      if (!v.empty() && v.back() == '"') v.pop_back();
      return v;
    }
  return "unknown";
}

}  // namespace

Json build_provenance() {
  const std::string_view commit = PXFLOW_COMMIT;
  // `git describe --dirty` (hosts/CMakeLists.txt) ends the commit with "-dirty" when the tree had
  // uncommitted changes at configure time.
  const bool dirty = commit.ends_with("-dirty");
  return Json{{"version", PXFLOW_VERSION},
              {"commit", commit.substr(0, dirty ? commit.size() - 6 : commit.size())},
              {"dirty", dirty},
              {"compiler", PXFLOW_COMPILER},
              {"build_type", PXFLOW_BUILD_TYPE},
              {"cxx_flags", PXFLOW_CXX_FLAGS}};
}

Json machine_provenance() {
  const auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  char host[256] = "unknown";
  gethostname(host, sizeof host - 1);
  utsname u{};
  const std::string kernel =
      uname(&u) == 0 ? std::string(u.sysname) + " " + u.release + " " + u.machine : "unknown";
  return Json{{"cpu", first_value_of("/proc/cpuinfo", "model name")},
              {"cores", std::thread::hardware_concurrency()},
              {"os", first_value_of("/etc/os-release", "PRETTY_NAME")},
              {"kernel", kernel},
              {"host", host},
              {"date", date}};
}

Json describe_backend(const std::string& name, const Backend& backend) {
  const Backend::Description d = backend.describe();
  Json j{{"backend", name}};
  if (!d.implementation.empty()) j["implementation"] = d.implementation;
  if (!d.device.empty()) j["device"] = d.device;
  if (!d.driver.empty()) j["driver"] = d.driver;
  return j;
}

std::string description_line(const Json& described) {
  std::string line;
  for (const char* key : {"implementation", "device", "driver"}) {
    if (!described.contains(key)) continue;
    if (!line.empty()) line += "; ";
    if (std::string_view(key) != "implementation") line += std::string(key) + " ";
    line += described[key].get<std::string>();
  }
  return line;
}

}  // namespace pxflow
