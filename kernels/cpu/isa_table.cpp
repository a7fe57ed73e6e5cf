// The rows of isas.def, expanded twice: once for the feature tests of the rows compiled here,
// once for the table itself. Compiled without ISA flags: it only takes the accessors' addresses.
#include "isa_table.hpp"

#include "isa_arch.hpp"

namespace pxflow::cpu {
namespace {

#define PXFLOW_CPU_ISA(name, arch, flags, ceiling, needs, test) \
  PXFLOW_CPU_ISA_IF_##arch(                                     \
      bool name##_cpu_has() { return test; }, )
#include "isas.def"
#undef PXFLOW_CPU_ISA

constexpr IsaInfo kIsas[] = {
#define PXFLOW_CPU_ISA(name, arch, flags, ceiling, needs, test)                \
  {#name, needs, #ceiling, PXFLOW_CPU_ISA_IF_##arch(&name##_cpu_has, nullptr), \
   PXFLOW_CPU_ISA_IF_##arch(&name##_kernel, nullptr)},
#include "isas.def"
#undef PXFLOW_CPU_ISA
};

}  // namespace

std::span<const IsaInfo> isa_table() { return kIsas; }

const IsaInfo* find_isa(std::string_view name) {
  for (const IsaInfo& isa : kIsas)
    if (name == isa.name) return &isa;
  return nullptr;
}

std::string known_isas() {
  std::string names;
  for (const IsaInfo& isa : kIsas) names += (names.empty() ? "" : ", ") + std::string(isa.name);
  return names;
}

}  // namespace pxflow::cpu
