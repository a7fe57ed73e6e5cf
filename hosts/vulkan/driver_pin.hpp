// The shared objects vkCreateInstance loads (the driver and the libraries it needs) stay mapped
// until the process exits. Mesa keeps one-time data in its globals (on AMD CPUs, lavapipe's L3
// cache affinity masks, made once per process by a realloc); the loader unloads the driver at
// vkDestroyInstance, which leaves that block unreachable, and LeakSanitizer reports it (128-768
// bytes per process, from an "<unknown module>": the driver is gone, so no suppression could
// name it). Kept mapped, the block stays reachable from the driver's globals, and a second
// instance does not load and initialise the driver again.
#pragma once

#include <set>
#include <string>

namespace pxflow::vk {

// The names of the shared objects mapped now.
std::set<std::string> loaded_objects();

// Takes a reference to every shared object mapped now that `before` does not name (dlopen with
// RTLD_NOLOAD, never closed).
void pin_objects_loaded_since(const std::set<std::string>& before);

}  // namespace pxflow::vk
