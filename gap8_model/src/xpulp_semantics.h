// The semantics column of gap8_model/isa/xpulp.tbl as one inline function per op,
// xpulp_semantics::<Op>(d, a, b, c): a = rs1, b = operand b, c = rd's value. Included by the
// interpreter (the `core` path) and by EvaluateXpulp (the `eval` path).
#pragma once

#include <cstdint>
#include <functional>

#include "gap8/decoded.h"
#include "gap8/xpulp.h"

namespace gap8::xpulp_semantics {

using namespace xpulp;  // NOLINT: the table's expressions name xpulp.h's functions unqualified
using s8 = int8_t;
using u8 = uint8_t;
using s16 = int16_t;
using u16 = uint16_t;

#include "gap8/xpulp_semantics.inc"

}  // namespace gap8::xpulp_semantics
