#include "isa_mask.hpp"

#include <algorithm>
#include <cstdlib>
#include <mutex>

#include "errors.hpp"
#include "isa_table.hpp"

namespace pxflow::cpu {
namespace {

constexpr const char* kEnvironment = kDisableEnvironment;

struct Mask {
  std::vector<std::string> names;
  std::string source;  // kEnvironment or "--disable-isa"
  std::string error;   // a bad PXFLOW_DISABLE value, reported by every probe
};

std::mutex mask_mutex;

const IsaInfo& known(std::string_view name, std::string_view source) {
  if (const IsaInfo* isa = find_isa(name)) return *isa;
  throw InputError(std::string(source) + ": unknown ISA '" + std::string(name) +
                   "' (known: " + known_isas() + ")");
}

// Splits "a,b" into names; an unknown name throws InputError.
std::vector<std::string> parse_list(std::string_view list, std::string_view source) {
  std::vector<std::string> names;
  while (!list.empty()) {
    const std::size_t comma = list.find(',');
    std::string name(list.substr(0, comma));
    list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
    name.erase(std::remove(name.begin(), name.end(), ' '), name.end());
    if (name.empty()) continue;
    names.push_back(known(name, source).name);
  }
  return names;
}

Mask& mask() {
  static Mask m = [] {
    Mask from_env{{}, kEnvironment, {}};
    if (const char* env = std::getenv(kEnvironment)) {
      try {
        from_env.names = parse_list(env, kEnvironment);
      } catch (const InputError& e) {
        from_env.error = e.what();
      }
    }
    return from_env;
  }();
  return m;
}

}  // namespace

const std::vector<std::string>& compiled_isas() {
  static const std::vector<std::string> isas = [] {
    std::vector<std::string> names;
    for (const IsaInfo& isa : isa_table())
      if (isa.compiled()) names.push_back(isa.name);
    return names;
  }();
  return isas;
}

void check_environment() {
  if (const char* env = std::getenv(kEnvironment)) parse_list(env, kEnvironment);
}

void set_disabled_isas(std::string_view list) {
  std::vector<std::string> names = parse_list(list, "--disable-isa");
  const std::lock_guard lock(mask_mutex);
  mask() = Mask{std::move(names), "--disable-isa", {}};
}

std::string isa_unavailable(std::string_view name) {
  const IsaInfo& isa = known(name, "cpu");
  if (!isa.compiled()) return std::string(isa.name) + " is not compiled into this build";
  {
    const std::lock_guard lock(mask_mutex);
    const Mask& m = mask();
    if (!m.error.empty()) return m.error;
    if (std::find(m.names.begin(), m.names.end(), name) != m.names.end())
      return "masked by " + m.source;
  }
  if (!isa.cpu_has()) return std::string("this CPU (or its OS) lacks it: needs ") + isa.needs;
  return "";
}

std::string best_isa() {
  const auto& compiled = compiled_isas();
  for (auto it = compiled.rbegin(); it != compiled.rend(); ++it)
    if (isa_unavailable(*it).empty()) return *it;
  return {};
}

}  // namespace pxflow::cpu
