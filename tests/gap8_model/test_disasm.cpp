// The disassembler (generated from isa/rv32imc.tbl and isa/xpulp.tbl) against two outside
// sources and the model's decoder: GreenWaves' assembler syntax for every Xpulp encoding, and
// for every RVC parcel and many 32-bit words the decoder's op and registers read and written.
// GNU objdump's text of whole ELFs: test_disasm_objdump.cpp.
#include <catch2/catch.hpp>
#include <cctype>
#include <random>
#include <set>
#include <string>

#include "gap8/decoded.h"
#include "gap8/disasm.h"
#include "xpulp_asm.h"

namespace {

constexpr uint32_t kPc = 0x1c000100;

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string Hex(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%x", v);
  return buf;
}

uint32_t Field(uint32_t w, int hi, int lo) { return (w >> lo) & ((1u << (hi - lo + 1)) - 1u); }

int32_t Signed(uint32_t v, int bits) {
  return static_cast<int32_t>(v << (32 - bits)) >> (32 - bits);
}

// The binutils operand letters of xgap8_opcodes.txt (its header), split: "d,o(s!)" -> d o s.
template <typename F>
void ForEachLetter(const std::string& operands, F f) {
  std::string token;
  for (const char c : operands + ",") {
    if (c == ',' || c == '(' || c == ')' || c == '!') {
      if (!token.empty()) f(token, c);
      token.clear();
    } else {
      token += c;
    }
  }
}

// A word of the row with every operand set to a value that shows its field and sign: d a0,
// s a1, t a2; the .sci immediate 0x3b (-5 signed, 59 unsigned); Is2 5, Is3 3; offsets -4; a
// branch +8 with the 5-bit immediate -3; loop 1, count 291, loop ends +0x20 and +14.
uint32_t Place(const xpulp_asm::OutsideRow& r) {
  uint32_t w = r.match;
  ForEachLetter(r.operands, [&](const std::string& tok, char) {
    if (tok == "d") w |= 10u << 7;
    if (tok == "s") w |= 11u << 15;
    if (tok == "t") w |= 12u << 20;
    if (tok == "bs" || tok == "bu" || tok == "bU" || tok == "bf" || tok == "bF")
      w |= (1u << 25) | (0x1du << 20);
    if (tok == "bi") w |= 5u << 20;
    if (tok == "b5") w |= 3u << 25;
    if (tok == "o") w |= 0xffcu << 20;
    if (tok == "q") w |= (0x7fu << 25) | (0x1cu << 7);
    if (tok == "p") w |= 4u << 8;
    if (tok == "bI") w |= 0x1du << 20;
    if (tok == "di") w |= 1u << 7;
    if (tok == "ji") w |= 0x123u << 20;
    if (tok == "b1") w |= 0x10u << 20;
    if (tok == "b2") w |= 7u << 15;
  });
  return w;
}

// The row's syntax with the word's operands, each letter read back from its field as binutils
// defines it: registers by ABI name, immediates in decimal, targets as hex addresses.
std::string Render(const xpulp_asm::OutsideRow& r, uint32_t w) {
  static const char* kAbi[32] = {"zero", "ra", "sp",  "gp",  "tp", "t0", "t1", "t2",
                                 "s0",   "s1", "a0",  "a1",  "a2", "a3", "a4", "a5",
                                 "a6",   "a7", "s2",  "s3",  "s4", "s5", "s6", "s7",
                                 "s8",   "s9", "s10", "s11", "t3", "t4", "t5", "t6"};
  const uint32_t imm6 = (Field(w, 24, 20) << 1) | Field(w, 25, 25);
  std::string out = Lower(r.mnemonic) + " ";
  ForEachLetter(r.operands, [&](const std::string& tok, char after) {
    if (tok == "d")
      out += kAbi[Field(w, 11, 7)];
    else if (tok == "s")
      out += kAbi[Field(w, 19, 15)];
    else if (tok == "t")
      out += kAbi[Field(w, 24, 20)];
    else if (tok == "bs")
      out += std::to_string(Signed(imm6, 6));
    else if (tok == "bu" || tok == "bU" || tok == "bf" || tok == "bF")
      out += std::to_string(imm6);
    else if (tok == "bi")
      out += std::to_string(Field(w, 24, 20));
    else if (tok == "b5")
      out += std::to_string(Field(w, 29, 25));
    else if (tok == "o")
      out += std::to_string(Signed(Field(w, 31, 20), 12));
    else if (tok == "q")
      out += std::to_string(Signed((Field(w, 31, 25) << 5) | Field(w, 11, 7), 12));
    else if (tok == "p")
      out += Hex(kPc + Signed((Field(w, 31, 31) << 12) | (Field(w, 7, 7) << 11) |
                                  (Field(w, 30, 25) << 5) | (Field(w, 11, 8) << 1),
                              13));
    else if (tok == "bI")
      out += std::to_string(Signed(Field(w, 24, 20), 5));
    else if (tok == "di")
      out += std::to_string(Field(w, 7, 7));
    else if (tok == "ji")
      out += std::to_string(Field(w, 31, 20));
    else if (tok == "b1")
      out += Hex(kPc + (Field(w, 31, 20) << 1));
    else if (tok == "b2")
      out += Hex(kPc + (Field(w, 19, 15) << 1));
    else
      FAIL("unknown operand letter " << tok);
    if (after == '(') out += "(";
    if (after == '!') out += "!)";
    if (after == ')') out += ")";
    if (after == ',') out += ",";
  });
  if (out.back() == ',') out.pop_back();  // the last letter's
  return out;
}

// The decoder's registers: what the disassembler's reads and writes must be.
void CheckRegisters(uint32_t bits) {
  const gap8::Decoded d = gap8::Decode(bits);
  const gap8::Disassembly s = gap8::Disassemble(bits, kPc);
  INFO(std::hex << "bits 0x" << bits << " " << s.text);
  REQUIRE(s.op == d.op);
  if (d.op == gap8::Op::kIllegal) return;
  CHECK(s.size == d.size);
  CHECK(s.reads == d.src_mask);
  const uint32_t rs1_written = s.post_increment ? (d.rs1 ? 1u << d.rs1 : 0u) : 0u;
  // A store's rd field is no destination (p.s* .rr: the offset register rs3).
  const bool store = (d.access & gap8::kAccessStore) != 0;
  CHECK(s.writes == ((store ? 0u : d.rd_bit) | rs1_written));
}

}  // namespace

TEST_CASE("the disassembly of every Xpulp encoding is GreenWaves' assembler syntax") {
  const std::set<std::string> left_out = {"pv.vitop.max", "pv.vitop.sel", "pv.cplxmul.sc.s",
                                          "pv.cplxmul.sci.s"};
  const auto& table = xpulp_asm::OutsideTable();
  int checked = 0;
  for (const xpulp_asm::OutsideRow& r : table) {
    if (left_out.count(r.mnemonic)) continue;
    const uint32_t w = Place(r);
    // The texts the assembler would accept for w: every row it matches (p.addn and its alias
    // p.addni; p.mulsn with Is3 0 and p.muls), named as the base ISA names its own (p.lw
    // a0,-4(a1) is lw, p.mul is mul).
    const bool base_isa = !gap8::IsXpulp(gap8::Decode(w).op);
    std::set<std::string> accepted;
    for (const xpulp_asm::OutsideRow& other : table) {
      if ((w & other.mask) != other.match) continue;
      const std::string text = Render(other, w);
      accepted.insert(base_isa && text.rfind("p.", 0) == 0 ? text.substr(2) : text);
    }
    const std::string ours = gap8::DisassembleText(w, kPc);
    INFO(r.mnemonic << " " << r.operands << std::hex << " bits 0x" << w << ": " << ours);
    CHECK(accepted.count(ours) == 1);
    ++checked;
  }
  CHECK(checked == 355);
}

TEST_CASE("the disassembler's op and registers are the decoder's for every RVC parcel") {
  int known = 0;
  for (uint32_t h = 0; h < 0x10000; ++h) {
    if (!gap8::IsCompressed(h)) continue;
    CheckRegisters(h);
    known += gap8::Disassemble(h, kPc).known;
  }
  CHECK(known > 25000);  // the table was read: most parcels are instructions
}

TEST_CASE("the disassembler's op and registers are the decoder's for 32-bit words") {
  // Every major opcode the model knows, with random other bits, and csrr mhartid.
  static constexpr uint32_t kMajor[] = {0x03, 0x0b, 0x0f, 0x13, 0x17, 0x23, 0x2b, 0x33,
                                        0x37, 0x57, 0x5b, 0x63, 0x67, 0x6f, 0x73, 0x7b};
  std::mt19937 rng(39);
  int known = 0;
  for (int i = 0; i < 400000; ++i) {
    const uint32_t w = (rng() & ~0x7Fu) | kMajor[i % std::size(kMajor)];
    CheckRegisters(w);
    known += gap8::Disassemble(w, kPc).known;
  }
  CheckRegisters(0xf1402573u);  // csrrs a0,mhartid,zero
  CheckRegisters(0xf14ca2f3u);  // csrrs with rs1 != x0: not modelled, illegal in both
  CHECK(known > 100000);
}

TEST_CASE("the disassembler's text names registers, immediates and targets as objdump does") {
  CHECK(gap8::DisassembleText(0xf1402573u, kPc) == "csrrs a0,mhartid,zero");
  CHECK(gap8::DisassembleText(0x00008067u, kPc) == "jalr zero,0(ra)");
  CHECK(gap8::DisassembleText(0x4065d513u, kPc) == "srai a0,a1,0x6");
  CHECK(gap8::DisassembleText(0x0ff0000fu, kPc) == "fence iorw,iorw");
  CHECK(gap8::DisassembleText(0x7579u, kPc) == "c.lui a0,0xffffe");
  CHECK(gap8::DisassembleText(0x0004u, kPc) == "reserved");  // c.addi4spn with 0
  CHECK(gap8::DisassembleText(0x0000u, kPc) == "c.unimp");
  CHECK(gap8::DisassembleText(0x0000a002u, kPc) == "unknown");  // c.fsdsp: no FPU
  CHECK(gap8::DisassembleText(0x0045a50bu, kPc) == "p.lw a0,4(a1!)");
  CHECK(gap8::DisassembleText(0x0000a001u, kPc) == "c.j " + Hex(kPc));
}
