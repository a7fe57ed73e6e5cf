#include "xpulp_asm.h"

#include <string>
#include <vector>

namespace xpulp_asm {
namespace {

constexpr uint32_t R(uint32_t opcode, uint32_t f3, uint32_t f7, uint32_t rs2 = kRs2) {
  return (f7 << 25) | (rs2 << 20) | (kRs1 << 15) | (f3 << 12) | (kRd << 7) | opcode;
}

std::vector<std::string_view> Split(std::string_view s) {
  std::vector<std::string_view> parts;
  size_t start = 0;
  for (size_t i = 0; i <= s.size(); ++i) {
    if (i == s.size() || s[i] == '.') {
      parts.push_back(s.substr(start, i - start));
      start = i + 1;
    }
  }
  return parts;
}

// funct6 of the packed-SIMD operations, bits 31..26 of opcode 1010111.
int SimdFunct6(std::string_view op) {
  static constexpr std::pair<std::string_view, int> kTable[] = {
      {"add", 0x00},       {"sub", 0x02},       {"avg", 0x04},       {"avgu", 0x06},
      {"min", 0x08},       {"minu", 0x0A},      {"max", 0x0C},       {"maxu", 0x0E},
      {"srl", 0x10},       {"sra", 0x12},       {"sll", 0x14},       {"or", 0x16},
      {"xor", 0x18},       {"and", 0x1A},       {"abs", 0x1C},       {"extract", 0x1E},
      {"extractu", 0x24},  {"insert", 0x2C},    {"dotup", 0x20},     {"dotusp", 0x22},
      {"dotsp", 0x26},     {"sdotup", 0x28},    {"sdotusp", 0x2A},   {"sdotsp", 0x2E},
      {"shuffle", 0x30},   {"shufflei0", 0x30}, {"shufflei1", 0x3A}, {"shufflei2", 0x3C},
      {"shufflei3", 0x3E}, {"shuffle2", 0x32},  {"pack", 0x34},      {"packhi", 0x36},
      {"packlo", 0x38},    {"cmpeq", 0x01},     {"cmpne", 0x03},     {"cmpgt", 0x05},
      {"cmpge", 0x07},     {"cmplt", 0x09},     {"cmple", 0x0B},     {"cmpgtu", 0x0D},
      {"cmpgeu", 0x0F},    {"cmpltu", 0x11},    {"cmpleu", 0x13},
  };
  for (const auto& [name, f6] : kTable)
    if (name == op) return f6;
  return -1;
}

bool AlwaysImmediate(std::string_view op) {
  return op == "extract" || op == "extractu" || op == "insert" || op.substr(0, 8) == "shufflei";
}

uint32_t Simd(const std::vector<std::string_view>& p, uint32_t imm) {
  const int f6 = SimdFunct6(p[1]);
  if (f6 < 0) return 0;
  bool sc = false, sci = AlwaysImmediate(p[1]), half = false;
  for (size_t i = 2; i < p.size(); ++i) {
    if (p[i] == "sc") sc = true;
    if (p[i] == "sci") sci = true;
    if (p[i] == "h") half = true;
  }
  const uint32_t f3 = (half ? 0u : 1u) | (sc ? 4u : 0u) | (sci ? 6u : 0u);
  uint32_t w = (static_cast<uint32_t>(f6) << 26) | (kRs2 << 20) | (kRs1 << 15) | (f3 << 12) |
               (kRd << 7) | 0x57;
  if (sci) {  // imm[0] -> bit 25, imm[5:1] -> bits 24..20
    w &= ~(0x3Fu << 20);
    w |= ((imm & 1u) << 25) | (((imm >> 1) & 0x1Fu) << 20);
  }
  if (p[1] == "abs") w &= ~(0x1Fu << 20);
  return w;
}

struct Named {
  std::string_view name;
  uint32_t word;
};

uint32_t Scalar(std::string_view m, uint32_t imm) {
  const uint32_t i5 = imm & 31u, is3 = (imm >> 5) & 31u;
  const uint32_t bitfield = (3u << 30) | (is3 << 25) | (i5 << 20);
  const Named table[] = {
      {"p.abs", R(0x33, 0, 0x02, 0)},
      {"p.avgu", R(0x33, 1, 0x02)},
      {"p.slet", R(0x33, 2, 0x02)},
      {"p.sletu", R(0x33, 3, 0x02)},
      {"p.min", R(0x33, 4, 0x02)},
      {"p.minu", R(0x33, 5, 0x02)},
      {"p.max", R(0x33, 6, 0x02)},
      {"p.maxu", R(0x33, 7, 0x02)},
      {"p.ror", R(0x33, 5, 0x04)},
      {"p.ff1", R(0x33, 0, 0x08, 0)},
      {"p.fl1", R(0x33, 1, 0x08, 0)},
      {"p.clb", R(0x33, 2, 0x08, 0)},
      {"p.cnt", R(0x33, 3, 0x08, 0)},
      {"p.exths", R(0x33, 4, 0x08, 0)},
      {"p.exthz", R(0x33, 5, 0x08, 0)},
      {"p.extbs", R(0x33, 6, 0x08, 0)},
      {"p.extbz", R(0x33, 7, 0x08, 0)},
      {"p.clip", R(0x33, 1, 0x0A, i5)},
      {"p.clipu", R(0x33, 2, 0x0A, i5)},
      {"p.clipr", R(0x33, 5, 0x0A)},
      {"p.clipur", R(0x33, 6, 0x0A)},
      {"p.mac", R(0x33, 0, 0x21)},
      {"p.msu", R(0x33, 1, 0x21)},
      {"p.extract", (R(0x33, 0, 0, 0) | bitfield)},
      {"p.extractu", (R(0x33, 1, 0, 0) | bitfield)},
      {"p.insert", (R(0x33, 2, 0, 0) | bitfield)},
      {"p.bclr", (R(0x33, 3, 0, 0) | bitfield)},
      {"p.bset", (R(0x33, 4, 0, 0) | bitfield)},
      {"p.extractr", R(0x33, 0, 0x40)},
      {"p.extractur", R(0x33, 1, 0x40)},
      {"p.insertr", R(0x33, 2, 0x40)},
      {"p.bclrr", R(0x33, 3, 0x40)},
      {"p.bsetr", R(0x33, 4, 0x40)},
      // opcode 1011011: bits 31..30 select the variant, 29..25 hold Is3
      {"p.mulu", R(0x5B, 0, 0x00)},
      {"p.mulhhu", R(0x5B, 0, 0x20)},
      {"p.muls", R(0x5B, 0, 0x40)},
      {"p.mulhhs", R(0x5B, 0, 0x60)},
      {"p.muluN", R(0x5B, 0, 0x00 | i5)},
      {"p.mulhhuN", R(0x5B, 0, 0x20 | i5)},
      {"p.mulsN", R(0x5B, 0, 0x40 | i5)},
      {"p.mulhhsN", R(0x5B, 0, 0x60 | i5)},
      {"p.muluRN", R(0x5B, 4, 0x00 | i5)},
      {"p.mulhhuRN", R(0x5B, 4, 0x20 | i5)},
      {"p.mulsRN", R(0x5B, 4, 0x40 | i5)},
      {"p.mulhhsRN", R(0x5B, 4, 0x60 | i5)},
      {"p.macu", R(0x5B, 1, 0x00)},
      {"p.machhu", R(0x5B, 1, 0x20)},
      {"p.macs", R(0x5B, 1, 0x40)},
      {"p.machhs", R(0x5B, 1, 0x60)},
      {"p.macuN", R(0x5B, 1, 0x00 | i5)},
      {"p.machhuN", R(0x5B, 1, 0x20 | i5)},
      {"p.macsN", R(0x5B, 1, 0x40 | i5)},
      {"p.machhsN", R(0x5B, 1, 0x60 | i5)},
      {"p.macuRN", R(0x5B, 5, 0x00 | i5)},
      {"p.machhuRN", R(0x5B, 5, 0x20 | i5)},
      {"p.macsRN", R(0x5B, 5, 0x40 | i5)},
      {"p.machhsRN", R(0x5B, 5, 0x60 | i5)},
      {"p.addN", R(0x5B, 2, 0x00 | i5)},
      {"p.adduN", R(0x5B, 2, 0x40 | i5)},
      {"p.addRN", R(0x5B, 6, 0x00 | i5)},
      {"p.adduRN", R(0x5B, 6, 0x40 | i5)},
      {"p.subN", R(0x5B, 3, 0x00 | i5)},
      {"p.subuN", R(0x5B, 3, 0x40 | i5)},
      {"p.subRN", R(0x5B, 7, 0x00 | i5)},
      {"p.subuRN", R(0x5B, 7, 0x40 | i5)},
      {"p.addNr", R(0x5B, 2, 0x20)},
      {"p.adduNr", R(0x5B, 2, 0x60)},
      {"p.addRNr", R(0x5B, 6, 0x20)},
      {"p.adduRNr", R(0x5B, 6, 0x60)},
      {"p.subNr", R(0x5B, 3, 0x20)},
      {"p.subuNr", R(0x5B, 3, 0x60)},
      {"p.subRNr", R(0x5B, 7, 0x20)},
      {"p.subuRNr", R(0x5B, 7, 0x60)},
  };
  for (const Named& n : table)
    if (n.name == m) return n.word;
  return 0;
}

// GAP8's own SIMD extensions [gap_sdk GVSOC isa_riscv_gen.py, subset `gap8`].
uint32_t Gap8Only(std::string_view m) {
  const Named table[] = {
      {"pv.add.h.div2", R(0x57, 2, 0x00)},      {"pv.add.h.div4", R(0x57, 2, 0x01)},
      {"pv.add.b.div2", R(0x57, 3, 0x00)},      {"pv.add.b.div4", R(0x57, 3, 0x01)},
      {"pv.sub.h.div2", R(0x57, 2, 0x04)},      {"pv.sub.h.div4", R(0x57, 2, 0x05)},
      {"pv.sub.b.div2", R(0x57, 3, 0x04)},      {"pv.sub.b.div4", R(0x57, 3, 0x05)},
      {"pv.cplxmul.s", R(0x57, 0, 0x2A)},       {"pv.cplxmul.s.div2", R(0x57, 2, 0x2A)},
      {"pv.cplxmul.s.div4", R(0x57, 2, 0x2B)},  {"pv.cplxconj.h", R(0x57, 0, 0x2E, 0)},
      {"pv.subrotmj.h", R(0x57, 0, 0x36)},      {"pv.subrotmj.h.div2", R(0x57, 2, 0x36)},
      {"pv.subrotmj.h.div4", R(0x57, 2, 0x37)}, {"pv.pack.h.h", R(0x57, 6, 0x68)},
      {"pv.pack.l.h", R(0x57, 4, 0x68)},
  };
  for (const Named& n : table)
    if (n.name == m) return n.word;
  return 0;
}

}  // namespace

uint32_t Assemble(std::string_view mnemonic, uint32_t imm) {
  if (const uint32_t w = Gap8Only(mnemonic)) return w;
  const auto parts = Split(mnemonic);
  if (parts.size() >= 2 && parts[0] == "pv") return Simd(parts, imm);
  return Scalar(mnemonic, imm);
}

bool TakesImmediate(std::string_view m) {
  const auto parts = Split(m);
  if (parts.size() >= 2 && parts[0] == "pv") {
    if (AlwaysImmediate(parts[1])) return true;
    for (auto p : parts)
      if (p == "sci") return true;
    return false;
  }
  return m == "p.clip" || m == "p.clipu" || m == "p.extract" || m == "p.extractu" ||
         m == "p.insert" || m == "p.bclr" || m == "p.bset";
}

}  // namespace xpulp_asm
