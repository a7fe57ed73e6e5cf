// Each Xpulp instruction, decoded from its PULPv2 encoding (GreenWaves' assembler table,
// xgap8_opcodes.txt, through xpulp_asm) and executed, against results computed by hand.
#include <catch2/catch.hpp>

#include "core_fixture.h"
#include "xpulp_asm.h"

namespace {

// The instruction with rd = x10, rs1 = x11, rs2 = x12, from the outside encoding table.
uint32_t Asm(const char* mnemonic) { return xpulp_asm::Assemble(mnemonic); }

}  // namespace

TEST_CASE("pv.maxu.b / pv.minu.b per unsigned byte, and their .sc forms") {
  CoreFixture f;
  CHECK(f.RunR(Asm("pv.maxu.b"), 0x80FF1203u, 0x7F01F004u) == 0x80FFF004u);
  CHECK(f.RunR(Asm("pv.minu.b"), 0x80FF1203u, 0x7F01F004u) == 0x7F011203u);
  CHECK(f.RunR(Asm("pv.maxu.sc.b"), 0x80FF1203u, 0xAAAAAA10u) == 0x80FF1210u);
  CHECK(f.RunR(Asm("pv.minu.sc.b"), 0x80FF1203u, 0x00000010u) == 0x10101003u);
}

TEST_CASE("pv.sub.b / pv.add.b wrap per byte: .sc uses rs2's low byte") {
  CoreFixture f;
  CHECK(f.RunR(Asm("pv.sub.b"), 0x80FF1203u, 0x7F01F004u) == 0x01FE22FFu);
  CHECK(f.RunR(Asm("pv.sub.sc.b"), 0x00010203u, 0xFFFFFF01u) == 0xFF000102u);
  CHECK(f.RunR(Asm("pv.add.b"), 0xFF7F0180u, 0x01010180u) == 0x00800200u);
  CHECK(f.RunR(Asm("pv.add.sc.b"), 0x01020304u, 0x10u) == 0x11121314u);
}

TEST_CASE("pv.avgu.b adds in the 8-bit lane (carry lost), then shifts") {
  CoreFixture f;
  // pulp-platform/riscv-tests (xpulp-dev) pv_avgu; a 9-bit floor average would give 0xB66DB3AC.
  CHECK(f.RunR(Asm("pv.avgu.b"), 0x8F75F8E9u, 0xDD666F70u) == 0x366D332Cu);
  // Lanes: 0x80+0x7F=0xFF -> 0x7F; 0xFF+0x01 wraps to 0 -> 0; 0x12+0xF0 wraps to 0x02 -> 1;
  // 0x03+0x04 -> 3. Floor-of-9-bit would give 0x7F808103.
  CHECK(f.RunR(Asm("pv.avgu.b"), 0x80FF1203u, 0x7F01F004u) == 0x7F000103u);
  // Lane 0: 0xFF + 0xFE = 0x1FD wraps to 0xFD, >> 1 = 0x7E; the others 0x1FE -> 0xFE -> 0x7F.
  CHECK(f.RunR(Asm("pv.avgu.b"), 0xFFFFFFFFu, 0xFFFFFFFEu) == 0x7F7F7F7Eu);
}

TEST_CASE("pv.abs.b: per signed byte, -128 stays 0x80") {
  CoreFixture f;
  CHECK(f.RunR(Asm("pv.abs.b"), 0xFF80017Fu, 0) == 0x0180017Fu);
}

TEST_CASE("pv.dotup.b / pv.dotusp.b: unsigned x unsigned, unsigned x signed") {
  CoreFixture f;
  CHECK(f.RunR(Asm("pv.dotup.b"), 0x01020304u, 0x05060708u) == 70u);
  CHECK(f.RunR(Asm("pv.dotup.b"), 0xFFFFFFFFu, 0xFFFFFFFFu) == 4u * 255u * 255u);
  CHECK(f.RunR(Asm("pv.dotusp.b"), 0x000000FFu, 0x000000FFu) == static_cast<uint32_t>(-255));
  CHECK(f.RunR(Asm("pv.dotusp.b"), 0x02020202u, 0x80FF0102u) == static_cast<uint32_t>(-252));
  CHECK(f.RunR(Asm("pv.dotup.sc.b"), 0x01010101u, 0x3u) == 12u);
}

TEST_CASE("pv.sdotup.b / pv.sdotusp.b accumulate into rd, .sc forms too") {
  CoreFixture f;
  CHECK(f.RunR(Asm("pv.sdotup.b"), 0x01020304u, 0x05060708u, 1000) == 1070u);
  CHECK(f.RunR(Asm("pv.sdotup.sc.b"), 0x01020304u, 0xFF000002u, 5) == 25u);
  CHECK(f.RunR(Asm("pv.sdotusp.b"), 0x000000FFu, 0x000000FFu, 300) == 45u);
  CHECK(f.RunR(Asm("pv.sdotusp.sc.b"), 0x01010101u, 0x000000FEu, 0) == static_cast<uint32_t>(-8));
  CHECK(f.RunR(Asm("pv.sdotup.b"), 0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu) == 4u * 255u * 255u - 1);
}

TEST_CASE("p.abs, p.min, p.minu, p.max, p.maxu") {
  CoreFixture f;
  const uint32_t minus3 = static_cast<uint32_t>(-3);
  CHECK(f.RunR(Asm("p.abs"), static_cast<uint32_t>(-42), 0) == 42u);
  CHECK(f.RunR(Asm("p.abs"), 0x80000000u, 0) == 0x80000000u);
  CHECK(f.RunR(Asm("p.min"), minus3, 2) == minus3);
  CHECK(f.RunR(Asm("p.minu"), minus3, 2) == 2u);
  CHECK(f.RunR(Asm("p.max"), minus3, 2) == 2u);
  CHECK(f.RunR(Asm("p.maxu"), minus3, 2) == minus3);
}

TEST_CASE("post-increment and register-offset loads and stores") {
  CoreFixture f;
  const uint32_t data = GAP8_L1_BASE + 0x40;
  const uint8_t bytes[8] = {0x11, 0x22, 0x33, 0x44, 0x85, 0x66, 0x77, 0x88};
  f.memory.Write(data, bytes, 8);
  // p.lbu x10, 1(x11!) ; p.lh x10, x12(x11) ; p.lw x10, x12(x11!)
  f.RunR(EncodeI(0x0B, 4, 10, 11, 1), data, 0);
  CHECK(f.core.reg(10) == 0x11u);
  CHECK(f.core.reg(11) == data + 1);
  CHECK(f.RunR(EncodeR(0x03, 7, 0x08, 10, 11, 12), data, 4) == 0x00006685u);
  CHECK(f.RunR(EncodeR(0x03, 7, 0x00, 10, 11, 12), data, 4) == 0xFFFFFF85u);
  CHECK(f.RunR(EncodeR(0x0B, 7, 0x10, 10, 11, 12), data, 4) == 0x44332211u);
  CHECK(f.core.reg(11) == data + 4);
  // p.sw x12, 4(x11!) then p.sb x12, x10(x11): offset register in the rd field
  f.Load({(0u << 25) | (12u << 20) | (11u << 15) | (2u << 12) | (4u << 7) | 0x2B});
  f.core.set_reg(11, data);
  f.core.set_reg(12, 0xCAFEF00Du);
  f.core.Step();
  CHECK(f.core.reg(11) == data + 4);
  uint32_t word = 0;
  f.memory.Read(data, &word, 4);
  CHECK(word == 0xCAFEF00Du);
  f.Load({EncodeR(0x23, 4, 0, 10, 11, 12)});
  f.core.set_reg(10, 2);
  f.core.Step();
  uint8_t byte = 0;
  f.memory.Read(data + 4 + 2, &byte, 1);
  CHECK(byte == 0x0Du);
}

TEST_CASE("hardware loop: lp.setupi repeats the body, end is the last body instruction") {
  CoreFixture f;
  // lp.setupi L0, 5 iterations, end = pc + 8; body: addi x10, x10, 1 ; addi x11, x11, 2
  f.Load({EncodeI(0x7B, 5, 0, 4, 5), EncodeI(0x13, 0, 10, 10, 1), EncodeI(0x13, 0, 11, 11, 2),
          EncodeI(0x13, 0, 12, 12, 7)});
  for (int i = 0; i < 1 + 5 * 2 + 1; ++i) f.core.Step();
  CHECK(f.core.reg(10) == 5u);
  CHECK(f.core.reg(11) == 10u);
  CHECK(f.core.reg(12) == 7u);
  CHECK(f.core.pc() == CoreFixture::kCode + 16);
}
