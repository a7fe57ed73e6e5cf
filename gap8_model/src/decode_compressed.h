// RV32C: each compressed instruction decodes straight to its 32-bit equivalent's Decoded form.
#pragma once

#include <cstdint>

#include "gap8/decoded.h"

namespace gap8 {

Decoded DecodeCompressed(uint32_t half);

}  // namespace gap8
