#include "driver_pin.hpp"

#include <dlfcn.h>
#include <link.h>

namespace pxflow::vk {

std::set<std::string> loaded_objects() {
  std::set<std::string> names;
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* out) {
        if (info->dlpi_name && info->dlpi_name[0] != '\0')
          static_cast<std::set<std::string>*>(out)->insert(info->dlpi_name);
        return 0;
      },
      &names);
  return names;
}

void pin_objects_loaded_since(const std::set<std::string>& before) {
  for (const std::string& name : loaded_objects())
    if (!before.contains(name)) (void)dlopen(name.c_str(), RTLD_LAZY | RTLD_NOLOAD);
}

}  // namespace pxflow::vk
