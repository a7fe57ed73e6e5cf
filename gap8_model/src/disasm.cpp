// The disassembler: the generated rows of both instruction tables (gap8/disasm_rows.inc, from
// isa/gen_disasm.py) and the printing of each operand token of isa/isa_format.py. Not on the
// model's hot path: fault messages and gap8-run --trace only.
#include "gap8/disasm.h"

#include <cstdio>
#include <string_view>

#include "decode_fields.h"

namespace gap8 {
namespace {

// The register fields of isa_format.py's FIELDS, in its order.
enum Field : uint8_t { kRd, kRs1, kRs2, kCRs2, kCRs2p, kCRs1p, kSp, kRa, kFields };

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

uint32_t FieldRegister(Field f, uint32_t w) {
  switch (f) {
    case kRd:
      return Bits(w, 11, 7);
    case kRs1:
      return Bits(w, 19, 15);
    case kRs2:
      return Bits(w, 24, 20);
    case kCRs2:
      return Bits(w, 6, 2);
    case kCRs2p:
      return 8 + Bits(w, 4, 2);
    case kCRs1p:
      return 8 + Bits(w, 9, 7);
    case kSp:
      return 2;
    default:
      return 1;  // kRa
  }
}

uint32_t RegisterMask(uint8_t fields, uint32_t w) {
  uint32_t mask = 0;
  for (int f = 0; f < kFields; ++f)
    if (fields & (1u << f)) mask |= RegBit(FieldRegister(static_cast<Field>(f), w));
  return mask;
}

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

int32_t Imm6(uint32_t h) { return SignExtend((Bits(h, 12, 12) << 5) | Bits(h, 6, 2), 6); }

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
  if (t == "u20") return Hex0x(w >> 12);
  if (t == "jt")
    return HexNoPrefix(
        pc + static_cast<uint32_t>(SignExtend((Bits(w, 31, 31) << 20) | (Bits(w, 19, 12) << 12) |
                                                  (Bits(w, 20, 20) << 11) | (Bits(w, 30, 21) << 1),
                                              21)));
  if (t == "bt") return HexNoPrefix(pc + static_cast<uint32_t>(ImmB(w)));
  if (t == "i12") return Dec(ImmI(w));
  if (t == "s12") return Dec(ImmS(w));
  if (t == "shamt") return Hex0x(Bits(w, 24, 20));
  if (t == "csr") return Bits(w, 31, 20) == 0xF14 ? "mhartid" : Hex0x(Bits(w, 31, 20));
  if (t == "fence") return FenceSet(Bits(w, 27, 24)) + "," + FenceSet(Bits(w, 23, 20));
  if (t == "ci6") return Dec(Imm6(w));
  if (t == "cshamt") return Hex0x((Bits(w, 12, 12) << 5) | Bits(w, 6, 2));
  if (t == "clui") return Hex0x(static_cast<uint32_t>(Imm6(w)) & 0xFFFFFu);
  if (t == "c16sp")
    return Dec(SignExtend((Bits(w, 12, 12) << 9) | (Bits(w, 6, 6) << 4) | (Bits(w, 5, 5) << 6) |
                              (Bits(w, 4, 3) << 7) | (Bits(w, 2, 2) << 5),
                          10));
  if (t == "c4spn")
    return Dec((Bits(w, 12, 11) << 4) | (Bits(w, 10, 7) << 6) | (Bits(w, 6, 6) << 2) |
               (Bits(w, 5, 5) << 3));
  if (t == "clw") return Dec((Bits(w, 12, 10) << 3) | (Bits(w, 6, 6) << 2) | (Bits(w, 5, 5) << 6));
  if (t == "clwsp")
    return Dec((Bits(w, 12, 12) << 5) | (Bits(w, 6, 4) << 2) | (Bits(w, 3, 2) << 6));
  if (t == "cswsp") return Dec((Bits(w, 12, 9) << 2) | (Bits(w, 8, 7) << 6));
  if (t == "cj")
    return HexNoPrefix(
        pc + static_cast<uint32_t>(SignExtend((Bits(w, 12, 12) << 11) | (Bits(w, 11, 11) << 4) |
                                                  (Bits(w, 10, 9) << 8) | (Bits(w, 8, 8) << 10) |
                                                  (Bits(w, 7, 7) << 6) | (Bits(w, 6, 6) << 7) |
                                                  (Bits(w, 5, 3) << 1) | (Bits(w, 2, 2) << 5),
                                              12)));
  if (t == "cb")
    return HexNoPrefix(
        pc + static_cast<uint32_t>(SignExtend((Bits(w, 12, 12) << 8) | (Bits(w, 11, 10) << 3) |
                                                  (Bits(w, 6, 5) << 6) | (Bits(w, 4, 3) << 1) |
                                                  (Bits(w, 2, 2) << 5),
                                              9)));
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
  return "?";  // not reached: gen_disasm.py refuses unknown tokens
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
    d.reads = RegisterMask(r.reads, w);
    d.writes = RegisterMask(r.writes, w);
    d.post_increment = std::string_view(r.format).find('!') != std::string_view::npos;
    return d;
  }
  return d;
}

}  // namespace gap8
