// The GAP8 flow kernel's ELF images, embedded into the host binary at build time
// (kernels/gap8/CMakeLists.txt), so that a pxflow binary runs them without the build tree.
#pragma once
#include <cstdint>
#include <span>
#include <string_view>

namespace pxflow {

// The ELF of the variant called `variant` (one per row of gap8_variants(): original, local,
// global, fast); empty for any other name.
std::span<const std::uint8_t> gap8_kernel_elf(std::string_view variant);

}  // namespace pxflow
