#include "isa_mask.hpp"

#include <algorithm>
#include <cstdlib>
#include <mutex>

#include "errors.hpp"

namespace pxflow::cpu {
namespace {

// Every name the mask accepts, on any architecture, so that one PXFLOW_DISABLE value serves
// x86-64 and AArch64 CI jobs alike.
const std::vector<std::string> kKnownIsas = {"swar", "sse2", "sse41", "avx2", "avx512bw", "neon"};

struct Mask {
  std::vector<std::string> names;
  std::string source;  // "PXFLOW_DISABLE" or "--disable-isa"
  std::string error;   // a bad PXFLOW_DISABLE value, reported by every probe
};

std::mutex mask_mutex;

// Splits "a,b" into names; an unknown name throws InputError.
std::vector<std::string> parse_list(std::string_view list, std::string_view source) {
  std::vector<std::string> names;
  while (!list.empty()) {
    const std::size_t comma = list.find(',');
    std::string name(list.substr(0, comma));
    list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
    name.erase(std::remove(name.begin(), name.end(), ' '), name.end());
    if (name.empty()) continue;
    if (std::find(kKnownIsas.begin(), kKnownIsas.end(), name) == kKnownIsas.end())
      throw InputError(std::string(source) + ": unknown ISA '" + name +
                       "' (known: swar, sse2, sse41, avx2, avx512bw, neon)");
    names.push_back(name);
  }
  return names;
}

Mask& mask() {
  static Mask m = [] {
    Mask from_env{{}, "PXFLOW_DISABLE", {}};
    if (const char* env = std::getenv("PXFLOW_DISABLE")) {
      try {
        from_env.names = parse_list(env, "PXFLOW_DISABLE");
      } catch (const InputError& e) {
        from_env.error = e.what();
      }
    }
    return from_env;
  }();
  return m;
}

// "" when this CPU has the ISA; otherwise why not.
std::string cpu_lacks(std::string_view isa) {
#if defined(__x86_64__)
  __builtin_cpu_init();
  if (isa == "sse2") return __builtin_cpu_supports("sse2") ? "" : "this CPU lacks SSE2";
  if (isa == "sse41") return __builtin_cpu_supports("sse4.1") ? "" : "this CPU lacks SSE4.1";
  if (isa == "avx2") return __builtin_cpu_supports("avx2") ? "" : "this CPU (or OS) lacks AVX2";
  if (isa == "avx512bw")
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw")
               ? ""
               : "this CPU (or OS, or valgrind) lacks AVX-512BW";
#endif
  (void)isa;
  return "";  // swar runs anywhere; neon is part of every AArch64 CPU
}

}  // namespace

const std::vector<std::string>& compiled_isas() {
#if defined(__x86_64__)
  static const std::vector<std::string> isas = {"swar", "sse2", "sse41", "avx2", "avx512bw"};
#elif defined(__aarch64__)
  static const std::vector<std::string> isas = {"swar", "neon"};
#else
  static const std::vector<std::string> isas = {"swar"};
#endif
  return isas;
}

void set_disabled_isas(std::string_view list) {
  std::vector<std::string> names = parse_list(list, "--disable-isa");
  const std::lock_guard lock(mask_mutex);
  mask() = Mask{std::move(names), "--disable-isa", {}};
}

std::string isa_unavailable(std::string_view isa) {
  const auto& compiled = compiled_isas();
  if (std::find(compiled.begin(), compiled.end(), isa) == compiled.end())
    return std::string(isa) + " is not compiled into this build";
  {
    const std::lock_guard lock(mask_mutex);
    const Mask& m = mask();
    if (!m.error.empty()) return m.error;
    if (std::find(m.names.begin(), m.names.end(), isa) != m.names.end())
      return "masked by " + m.source;
  }
  return cpu_lacks(isa);
}

std::string best_isa() {
  const auto& compiled = compiled_isas();
  for (auto it = compiled.rbegin(); it != compiled.rend(); ++it)
    if (isa_unavailable(*it).empty()) return *it;
  return {};
}

}  // namespace pxflow::cpu
