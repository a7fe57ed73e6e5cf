// The hardware-loop rules of the RI5CY user manual (2018, "PULP Hardware Loop Extensions":
// "the minimum loop size is two instructions and the last instruction cannot be any jump or
// branch instruction"; "Loop counter has to be bigger than 0"), each a kHardwareLoop fault
// naming the rule at the offending instruction; and what the manual does not forbid still runs.
#include <catch2/catch.hpp>

#include "core_fixture.h"

namespace {

constexpr uint32_t kAddi1 = EncodeI(0x13, 0, 10, 10, 1);  // addi x10, x10, 1
constexpr uint32_t kBeqSelf = (11u << 20) | (11u << 15) | (0u << 12) | (8u << 7) | 0x63;  // +8
constexpr uint32_t kJalNext = (4u << 21) | 0x6F;  // jal x0, +4

// lp.setupi L0, count, end = pc + 2 * end_halfwords
constexpr uint32_t SetupI(uint32_t count, uint32_t end_halfwords) {
  return EncodeI(0x7B, 5, 0, end_halfwords, static_cast<int32_t>(count));
}

gap8::Fault RunUntilFault(CoreFixture& f, int max_steps = 64) {
  for (int i = 0; i < max_steps; ++i) {
    try {
      f.core.Step();
    } catch (const gap8::Fault& fault) {
      return fault;
    }
  }
  FAIL("no fault");
  return {};
}

}  // namespace

TEST_CASE("hardware loop rule: the last instruction must not be a branch") {
  CoreFixture f;
  // body: addi ; beq x11, x11, +8 (the loop's last instruction)
  f.Load({SetupI(3, 4), kAddi1, kBeqSelf, kAddi1, kAddi1});
  const gap8::Fault fault = RunUntilFault(f);
  CHECK(fault.kind == gap8::FaultKind::kHardwareLoop);
  CHECK(fault.pc == CoreFixture::kCode + 8);
  CHECK(fault.what ==
        "the last instruction of a hardware loop must not be a branch (RI5CY manual, hardware "
        "loops)");
}

TEST_CASE("hardware loop rule: the last instruction must not be a jump") {
  CoreFixture f;
  f.Load({SetupI(3, 4), kAddi1, kJalNext, kAddi1});
  const gap8::Fault fault = RunUntilFault(f);
  CHECK(fault.kind == gap8::FaultKind::kHardwareLoop);
  CHECK(fault.pc == CoreFixture::kCode + 8);
  CHECK(fault.what.find("must not be a jump") != std::string::npos);
}

TEST_CASE("hardware loop rule: a body of one instruction is refused") {
  CoreFixture f;
  f.Load({SetupI(3, 2), kAddi1, kAddi1});  // end = start: one instruction
  const gap8::Fault fault = RunUntilFault(f);
  CHECK(fault.kind == gap8::FaultKind::kHardwareLoop);
  CHECK(fault.pc == CoreFixture::kCode + 4);
  CHECK(fault.what.find("at least 2 instructions") != std::string::npos);
}

TEST_CASE("hardware loop rule: the count must be bigger than 0") {
  for (uint32_t setup : {SetupI(0, 4),                   // lp.setupi L0, 0
                         EncodeI(0x7B, 3, 0, 0, 0),      // lp.counti L0, 0
                         EncodeI(0x7B, 2, 0, 13, 0),     // lp.count L0, x13 (= 0)
                         EncodeI(0x7B, 4, 0, 13, 4)}) {  // lp.setup L0, x13, 8
    CoreFixture f;
    f.Load({setup, kAddi1, kAddi1});
    f.core.set_reg(13, 0);
    const gap8::Fault fault = RunUntilFault(f);
    CHECK(fault.kind == gap8::FaultKind::kHardwareLoop);
    CHECK(fault.pc == CoreFixture::kCode);
    CHECK(fault.what.find("bigger than 0") != std::string::npos);
  }
}

TEST_CASE("hardware loops: what the RI5CY manual allows still runs") {
  SECTION("a branch out of the body that is not its last instruction") {
    CoreFixture f;
    // body: beq x11, x11, +12 (to the addi after the loop) ; addi ; addi
    const uint32_t beq_out = (11u << 20) | (11u << 15) | (12u << 7) | 0x63;
    f.Load({SetupI(5, 6), beq_out, kAddi1, kAddi1, EncodeI(0x13, 0, 12, 12, 7)});
    for (int i = 0; i < 3; ++i) f.core.Step();
    CHECK(f.core.reg(12) == 7u);
    CHECK(f.core.reg(10) == 0u);
  }
  SECTION("nested loops sharing their end: loop 1 continues when loop 0 ends") {
    CoreFixture f;
    // lp.setupi L1, 2, end +12 ; lp.setupi L0, 3, end +8 ; addi ; addi
    f.Load({EncodeI(0x7B, 5, /*L=*/1, 6, 2), SetupI(3, 4), kAddi1, kAddi1,
            EncodeI(0x13, 0, 12, 12, 7)});
    for (int i = 0; i < 64 && f.core.reg(12) == 0; ++i) f.core.Step();
    // loop 1's body is lp.setupi L0 ... the shared end: 2 x (1 + 3 x 2) instructions
    CHECK(f.core.reg(10) == 2u * 3u * 2u);
    CHECK(f.core.pc() == CoreFixture::kCode + 20);
  }
}
