// Which CPU kernels may run here: compiled in, supported by this CPU (the feature test of its row
// in kernels/cpu/isas.def), and not masked. Masking lets one machine test every compiled path:
// PXFLOW_DISABLE=<name>,<name> in the environment, or set_disabled_isas() (the CLI's
// --disable-isa), which replaces it. A name the table does not know is an InputError either way.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace pxflow::cpu {

// The environment variable of the mask.
inline constexpr const char* kDisableEnvironment = "PXFLOW_DISABLE";

// The ISAs compiled into this build, weakest first (the table's rows of this architecture).
const std::vector<std::string>& compiled_isas();

// Throws the InputError of a bad PXFLOW_DISABLE value ("PXFLOW_DISABLE: unknown ISA 'x' (known:
// ...)"); the CLI calls it before every command, so that a typo is exit 2, not a skipped row.
void check_environment();

// Masks the ISAs of a comma-separated list (row names of the table; empty masks none) for the rest
// of the process, replacing PXFLOW_DISABLE. Throws InputError naming an unknown ISA.
void set_disabled_isas(std::string_view list);

// Empty when `isa` can run here; otherwise the one-line reason (not compiled, the CPU lacks it,
// masked by PXFLOW_DISABLE or --disable-isa, or a bad PXFLOW_DISABLE value). Throws InputError
// for a name the table does not know.
std::string isa_unavailable(std::string_view isa);

// The strongest ISA that can run here, or empty when every one is unavailable.
std::string best_isa();

}  // namespace pxflow::cpu
