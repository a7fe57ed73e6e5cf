#include "opencv_module.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "errors.hpp"

// Defined only in programs that link the module's code statically (weak: null otherwise).
extern "C" const pxflow::opencv::Api* pxflow_opencv_api() __attribute__((weak));

namespace pxflow {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> candidates() {
  if (const char* env = std::getenv("PXFLOW_OPENCV_MODULE"); env && *env) return {env};
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const fs::path dir = exe.parent_path();
  std::vector<fs::path> paths = {dir / kOpenCvModuleFile};
  // The install rule's folder relative to the binary's (GNUInstallDirs: ../lib/pxflow, or
  // ../lib/<multiarch>/pxflow under /usr), then ../lib/pxflow.
  for (const fs::path& rel : {fs::path(PXFLOW_OPENCV_MODULE_RELDIR), fs::path("../lib/pxflow")}) {
    const fs::path path = (dir / rel / kOpenCvModuleFile).lexically_normal();
    if (path != paths.back()) paths.push_back(path);
  }
  return paths;
}

// Loads the module, or returns why not.
const opencv::Api* load(std::string& why) {
  if (pxflow_opencv_api) return pxflow_opencv_api();
  const auto paths = candidates();
  if (paths.empty()) {
    why =
        "cannot be looked for beside the executable (/proc/self/exe unreadable); set "
        "PXFLOW_OPENCV_MODULE to its path";
    return nullptr;
  }
  std::string tried;
  for (const fs::path& path : paths) {
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      tried += (tried.empty() ? "" : ", ") + path.string();
      continue;
    }
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      why = "at " + path.string() + " cannot be loaded (" + ::dlerror() +
            "); reinstall pxflow, or install OpenCV's libraries (bash ci/install-deps.sh)";
      return nullptr;
    }
    using Entry = const opencv::Api* (*)();
    const auto entry = reinterpret_cast<Entry>(::dlsym(handle, opencv::kEntryPoint));
    const opencv::Api* api = entry ? entry() : nullptr;
    if (!api || api->version != opencv::kApiVersion) {
      why = "at " + path.string() + " is not this pxflow's (" +
            (api ? "interface version " + std::to_string(api->version) + ", this pxflow needs " +
                       std::to_string(opencv::kApiVersion)
                 : std::string("no ") + opencv::kEntryPoint) +
            "); rebuild or reinstall pxflow so that both come from the same build";
      return nullptr;
    }
    api->quiet();
    return api;
  }
  why = "is missing (looked for " + tried +
        "); rebuild pxflow (cmake --build build), reinstall it, or set PXFLOW_OPENCV_MODULE to "
        "its path";
  return nullptr;
}

}  // namespace

const opencv::Api& opencv_api() {
  static std::once_flag once;
  static const opencv::Api* api = nullptr;
  static std::string why;
  std::call_once(once, [] { api = load(why); });
  if (!api) throw InputError("the OpenCV module, needed to decode images and video, " + why);
  return *api;
}

}  // namespace pxflow
