// Decoder corner cases the differential test cannot reach (encodings it never generates).
#include <catch2/catch.hpp>

#include "core_fixture.h"
#include "gap8/decoded.h"
#include "xpulp_asm.h"

using gap8::Decode;
using gap8::Op;

TEST_CASE("reserved and FPU compressed encodings are illegal") {
  CHECK(Decode(0x0000).op == Op::kIllegal);              // all zero
  CHECK(Decode(0x0000 | (1u << 2)).op == Op::kIllegal);  // c.addi4spn with zero immediate
  CHECK(Decode(0x2000).op == Op::kIllegal);              // c.fld
  CHECK(Decode(0x6000).op == Op::kIllegal);              // c.flw
  CHECK(Decode(0x4002).op == Op::kIllegal);              // c.lwsp x0
  CHECK(Decode(0x8002).op == Op::kIllegal);              // c.jr x0
  CHECK(Decode(0x9002).op == Op::kIllegal);              // c.ebreak: no debugger modelled
  CHECK(Decode(0x1002 | (1u << 7)).op == Op::kIllegal);  // c.slli with shamt[5] on RV32
  CHECK(Decode(0x9C21).op == Op::kIllegal);              // c.subw (RV64)
}

TEST_CASE("compressed instructions expand to their 32-bit operations") {
  const gap8::Decoded add = Decode(0x9532);  // c.add x10, x12
  CHECK(add.op == Op::kAdd);
  CHECK(add.rd == 10);
  CHECK(add.rs1 == 10);
  CHECK(add.rs2 == 12);
  CHECK(add.size == 2);
  const gap8::Decoded lw = Decode(0x4188);  // c.lw x10, 0(x11)
  CHECK(lw.op == Op::kLoad);
  CHECK(lw.rd == 10);
  CHECK(lw.rs1 == 11);
  CHECK(lw.width == 2);
  const gap8::Decoded lui = Decode(0x7579);  // c.lui x10, 0xFFFFE (sign-extended)
  CHECK(lui.op == Op::kLui);
  CHECK(static_cast<uint32_t>(lui.imm) == 0xFFFFE000u);
}

TEST_CASE("system instructions other than csrr mhartid are illegal") {
  CHECK(Decode(0xF1402573).op == Op::kCsrRead);  // csrr a0, mhartid
  CHECK(Decode(0x00000073).op == Op::kIllegal);  // ecall
  CHECK(Decode(0x00100073).op == Op::kIllegal);  // ebreak
  CHECK(Decode(0xB0002573).op == Op::kIllegal);  // csrr a0, mcycle
}

TEST_CASE("csrr mhartid returns the core id") {
  gap8::Memory memory;
  gap8::Core core(5, memory, nullptr);
  const uint32_t word = 0xF1402573;
  memory.Write(GAP8_L2_BASE, &word, 4);
  core.set_pc(GAP8_L2_BASE);
  core.Step();
  CHECK(core.reg(10) == 5u);
}

TEST_CASE("source masks drive the hazard checks") {
  CHECK(Decode(EncodeR(0x33, 0, 0, 10, 11, 12)).src_mask == ((1u << 11) | (1u << 12)));
  CHECK(Decode(0x000502B7).src_mask == 0u);  // lui: the rs1 bits belong to the immediate
  CHECK(Decode(xpulp_asm::Assemble("pv.sdotup.b")).src_mask ==
        ((1u << 10) | (1u << 11) | (1u << 12)));
}

TEST_CASE("a fetch outside L1 and L2 is a memory fault naming the pc") {
  gap8::Memory memory;
  gap8::Core core(0, memory, nullptr);
  core.set_pc(0x20000000);
  try {
    core.Step();
    FAIL("no fault");
  } catch (const gap8::Fault& f) {
    CHECK(f.kind == gap8::FaultKind::kMemory);
    CHECK(f.Message() ==
          "core 0 at pc 0x20000000 (insn 0x00000000): instruction fetch from "
          "unmapped address 0x20000000");
  }
}

TEST_CASE("rewriting code invalidates the decode cache") {
  CoreFixture f;
  f.Load({EncodeI(0x13, 0, 10, 0, 1)});  // addi x10, x0, 1
  f.core.Step();
  CHECK(f.core.reg(10) == 1u);
  f.Load({EncodeI(0x13, 0, 10, 0, 2)});
  f.core.Step();
  CHECK(f.core.reg(10) == 2u);
}
