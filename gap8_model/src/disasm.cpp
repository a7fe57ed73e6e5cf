// The disassembler: the generated rows of both instruction tables (gap8/disasm_rows.inc, from
// isa/gen_disasm.py) and the printing of each operand token of isa/isa_format.py. Not on the
// model's hot path: fault messages and gap8-run --trace only.
#include "gap8/disasm.h"

#include <cstdio>
#include <string_view>

#include "decode_fields.h"

namespace gap8 {
namespace {

struct Row {
  uint32_t match, mask;
  uint8_t size;
  const char* mnemonic;
  const char* format;
  uint8_t reads, writes;  // Field bits
  Op op;
};

constexpr Row kRows[] = {
#include "gap8/disasm_rows.inc"
};

constexpr const char* kAbiNames[32] = {"zero", "ra", "sp",  "gp",  "tp", "t0", "t1", "t2",
                                       "s0",   "s1", "a0",  "a1",  "a2", "a3", "a4", "a5",
                                       "a6",   "a7", "s2",  "s3",  "s4", "s5", "s6", "s7",
                                       "s8",   "s9", "s10", "s11", "t3", "t4", "t5", "t6"};

// A register token of isa_format.py's REGISTERS ('!' and '+' stripped by the caller): its field.
bool RegisterToken(std::string_view t, Field* f) {
  static constexpr struct {
    std::string_view token;
    Field field;
  } kTokens[] = {{"rd", kRd},       {"rs1", kRs1},     {"rs2", kRs2},   {"rs3", kRd},
                 {"crd", kRd},      {"crs1", kRd},     {"crs2", kCRs2}, {"crd'", kCRs2p},
                 {"crs2'", kCRs2p}, {"crs1'", kCRs1p}, {"sp", kSp},     {"^ra", kRa}};
  for (const auto& k : kTokens) {
    if (k.token == t) {
      *f = k.field;
      return true;
    }
  }
  return false;
}

std::string Dec(int64_t v) { return std::to_string(v); }

std::string HexNoPrefix(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%x", v);
  return buf;
}

std::string Hex0x(uint32_t v) { return "0x" + HexNoPrefix(v); }

std::string FenceSet(uint32_t bits) {
  std::string s;
  const char* names = "iorw";
  for (int i = 0; i < 4; ++i)
    if (bits & (8u >> i)) s += names[i];
  return s.empty() ? "0" : s;
}

// The text of an immediate token (isa_format.py's IMMEDIATES), GNU objdump's way: decimal
// offsets and immediates, hex shift amounts and upper immediates, targets as bare hex addresses.
std::string Immediate(std::string_view t, uint32_t w, uint32_t pc) {
  const uint32_t imm6 = (Bits(w, 24, 20) << 1) | Bits(w, 25, 25);  // Xpulp .sci
  const auto target = [&](RvImm kind) {
    return HexNoPrefix(pc + static_cast<uint32_t>(RvImmediate(kind, w)));
  };
  const auto dec = [&](RvImm kind) { return Dec(RvImmediate(kind, w)); };
  if (t == "u20") return Hex0x(w >> 12);
  if (t == "jt") return target(RvImm::kJ);
  if (t == "bt") return target(RvImm::kB);
  if (t == "i12") return dec(RvImm::kI);
  if (t == "s12") return dec(RvImm::kS);
  if (t == "shamt") return Hex0x(Bits(w, 24, 20));
  if (t == "csr") return Bits(w, 31, 20) == 0xF14 ? "mhartid" : Hex0x(Bits(w, 31, 20));
  if (t == "fence") return FenceSet(Bits(w, 27, 24)) + "," + FenceSet(Bits(w, 23, 20));
  if (t == "ci6") return dec(RvImm::kCi6);
  if (t == "cshamt") return Hex0x(static_cast<uint32_t>(RvImmediate(RvImm::kCShamt, w)));
  if (t == "clui") return Hex0x(static_cast<uint32_t>(CImm6(w)) & 0xFFFFFu);
  if (t == "c16sp") return dec(RvImm::kC16sp);
  if (t == "c4spn") return dec(RvImm::kC4spn);
  if (t == "clw") return dec(RvImm::kClw);
  if (t == "clwsp") return dec(RvImm::kClwsp);
  if (t == "cswsp") return dec(RvImm::kCswsp);
  if (t == "cj") return target(RvImm::kCj);
  if (t == "cb") return target(RvImm::kCb);
  if (t == "simm6") return Dec(SignExtend(imm6, 6));
  if (t == "uimm6") return Dec(imm6);
  if (t == "is2") return Dec(Bits(w, 24, 20));
  if (t == "is3") return Dec(Bits(w, 29, 25));
  if (t == "bitfield") return Dec(Bits(w, 29, 25)) + "," + Dec(Bits(w, 24, 20));
  if (t == "simm5") return Dec(SignExtend(Bits(w, 24, 20), 5));
  if (t == "uimm12") return Dec(Bits(w, 31, 20));
  if (t == "loop") return Dec(Bits(w, 7, 7));
  if (t == "lt") return HexNoPrefix(pc + (Bits(w, 31, 20) << 1));
  if (t == "lt5") return HexNoPrefix(pc + (Bits(w, 19, 15) << 1));
  return "?";  // not reached: the generators refuse unknown tokens
}

// One operand token: a register's ABI name or an immediate's text; "" for a hidden register.
std::string Operand(std::string_view t, uint32_t w, uint32_t pc) {
  while (!t.empty() && (t.back() == '+' || t.back() == '!')) t.remove_suffix(1);
  Field f;
  if (RegisterToken(t, &f)) return t[0] == '^' ? "" : kAbiNames[FieldRegister(f, w)];
  return Immediate(t, w, pc);
}

std::string Operands(std::string_view format, uint32_t w, uint32_t pc) {
  std::string out;
  if (format == "-") return out;
  while (!format.empty()) {
    const size_t comma = format.find(',');
    std::string_view part = format.substr(0, comma);
    format = comma == std::string_view::npos ? std::string_view{} : format.substr(comma + 1);
    std::string text;
    const size_t open = part.find('(');
    if (open != std::string_view::npos) {  // OFFSET(BASE) or OFFSET(BASE!)
      const std::string_view base = part.substr(open + 1, part.size() - open - 2);
      text = Operand(part.substr(0, open), w, pc) + "(" + Operand(base, w, pc) +
             (base.back() == '!' ? "!)" : ")");
    } else {
      text = Operand(part, w, pc);
    }
    if (text.empty()) continue;
    if (!out.empty()) out += ',';
    out += text;
  }
  return out;
}

}  // namespace

Disassembly Disassemble(uint32_t bits, uint32_t pc) {
  Disassembly d;
  const bool rvc = IsCompressed(bits & 0xFFFFu);
  const uint32_t w = rvc ? bits & 0xFFFFu : bits;
  d.size = rvc ? 2 : 4;
  d.text = "unknown";
  for (const Row& r : kRows) {
    if (r.size != d.size || (w & r.mask) != r.match) continue;
    if (r.op == Op::kIllegal) {  // c.unimp or a reserved encoding
      d.text = r.mnemonic;
      return d;
    }
    d.known = true;
    d.op = r.op;
    const std::string operands = Operands(r.format, w, pc);
    d.text = operands.empty() ? r.mnemonic : std::string(r.mnemonic) + " " + operands;
    d.reads = FieldsMask(r.reads, w);
    d.writes = FieldsMask(r.writes, w);
    d.post_increment = std::string_view(r.format).find('!') != std::string_view::npos;
    return d;
  }
  return d;
}

}  // namespace gap8
