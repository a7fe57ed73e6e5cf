// Which CPU kernels may run here: compiled in, supported by this CPU (CPUID), and not masked.
// Masking lets one machine test every compiled path: PXFLOW_DISABLE=avx512bw,avx2 in the
// environment, or set_disabled_isas() (the CLI's --disable-isa), which replaces it.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace pxflow::cpu {

// The ISAs compiled into this build, weakest first ("swar", "sse2", "sse41", "avx2",
// "avx512bw" on x86-64; "swar", "neon" on AArch64).
const std::vector<std::string>& compiled_isas();

// Masks the ISAs of a comma-separated list (e.g. "avx512bw,avx2"; empty masks none) for the rest
// of the process, replacing PXFLOW_DISABLE. Throws InputError naming an unknown ISA.
void set_disabled_isas(std::string_view list);

// Empty when `isa` can run here; otherwise the one-line reason (not compiled, the CPU lacks it,
// masked by PXFLOW_DISABLE or --disable-isa, or a bad PXFLOW_DISABLE value).
std::string isa_unavailable(std::string_view isa);

// The strongest ISA that can run here, or empty when every one is unavailable.
std::string best_isa();

}  // namespace pxflow::cpu
