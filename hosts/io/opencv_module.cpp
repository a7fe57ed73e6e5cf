#include "opencv_module.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>

#include "errors.hpp"
#include "own_files.hpp"

// Defined only in programs that link the module's code statically (weak: null otherwise).
extern "C" const pxflow::opencv::Api* pxflow_opencv_api() __attribute__((weak));

namespace pxflow {
namespace {

namespace fs = std::filesystem;

// $PXFLOW_OPENCV_MODULE, else the folders of opencv_module.hpp, relative to the binary's.
OwnFile find_module() {
  if (const char* env = std::getenv("PXFLOW_OPENCV_MODULE"); env && *env) {
    OwnFile given{{}, {fs::path(env)}};
    std::error_code ec;
    if (fs::exists(given.tried[0], ec)) given.found = given.tried[0];
    return given;
  }
  return find_own_file(kOpenCvModuleFile, {".", PXFLOW_OPENCV_MODULE_RELDIR, "../lib/pxflow"});
}

// Loads the module, or returns why not.
const opencv::Api* load(std::string& why) {
  if (pxflow_opencv_api) return pxflow_opencv_api();
  const OwnFile module = find_module();
  if (module.tried.empty()) {
    why =
        "cannot be looked for beside the executable (/proc/self/exe unreadable); set "
        "PXFLOW_OPENCV_MODULE to its path";
    return nullptr;
  }
  if (module.found.empty()) {
    why = "is missing (looked for " + describe_tried(module.tried) +
          "); rebuild pxflow (cmake --build build), reinstall it, or set PXFLOW_OPENCV_MODULE to "
          "its path";
    return nullptr;
  }
  const fs::path& path = module.found;
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
