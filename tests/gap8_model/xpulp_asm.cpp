#include "xpulp_asm.h"

#include <cctype>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include "build_paths.hpp"

namespace xpulp_asm {
namespace {

struct Encoding {
  std::string operands;  // binutils operand syntax, e.g. "d,s,t,b5"
  uint32_t match = 0;
};

std::string Lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// The first row of a mnemonic wins (p.lb's four forms are not assembled here).
const std::map<std::string, Encoding>& Table() {
  static const std::map<std::string, Encoding> table = [] {
    std::map<std::string, Encoding> t;
    for (const OutsideRow& r : OutsideTable())
      t.emplace(Lower(r.mnemonic), Encoding{r.operands, r.match});
    return t;
  }();
  return table;
}

// Whether the operand syntax names `field`: "d,t(s!)" names d, t and s.
bool Has(const std::string& operands, std::string_view field) {
  std::string part;
  for (const char c : operands + ",") {
    if (c == ',' || c == '(' || c == ')' || c == '!') {
      if (part == field) return true;
      part.clear();
    } else {
      part += c;
    }
  }
  return false;
}

// Where each operand goes (RI5CY manual's encoding tables): d, s, t in the rd, rs1, rs2 fields
// (di, the loop number, is left 0); the 6-bit .sci immediate (bs, bu, bU, bf, bF) with imm[0]
// in bit 25 and imm[5:1] in bits 24..20; a 5-bit Is2 (bi) in bits 24..20; a 5-bit Is3 (b5) in
// bits 29..25.
uint32_t Place(const Encoding& e, uint32_t imm) {
  const std::string& ops = e.operands;
  uint32_t w = e.match;
  if (Has(ops, "d")) w |= static_cast<uint32_t>(kRd) << 7;
  if (Has(ops, "s")) w |= static_cast<uint32_t>(kRs1) << 15;
  if (Has(ops, "t")) w |= static_cast<uint32_t>(kRs2) << 20;
  for (const char* sci : {"bs", "bu", "bU", "bf", "bF"})
    if (Has(ops, sci)) w |= ((imm & 1u) << 25) | (((imm >> 1) & 31u) << 20);
  const bool two_fields = Has(ops, "b5") && Has(ops, "bi");  // bit fields: (Is3 << 5) | Is2
  if (Has(ops, "bi")) w |= (imm & 31u) << 20;
  if (Has(ops, "b5")) w |= ((two_fields ? imm >> 5 : imm) & 31u) << 25;
  return w;
}

}  // namespace

const std::vector<OutsideRow>& OutsideTable() {
  static const std::vector<OutsideRow> rows = [] {
    std::ifstream in(build_paths::xgap8_opcodes);
    if (!in) throw std::runtime_error(std::string("cannot read ") + build_paths::xgap8_opcodes);
    std::vector<OutsideRow> out;
    std::string line;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream fields(line);
      OutsideRow r;
      std::string match, mask;
      fields >> r.mnemonic >> r.operands >> match >> mask >> r.extension;
      r.match = static_cast<uint32_t>(std::stoul(match, nullptr, 16));
      r.mask = static_cast<uint32_t>(std::stoul(mask, nullptr, 16));
      out.push_back(r);
    }
    return out;
  }();
  return rows;
}

uint32_t Assemble(std::string_view mnemonic, uint32_t imm) {
  const auto it = Table().find(Lower(mnemonic));
  return it == Table().end() ? 0 : Place(it->second, imm);
}

bool TakesImmediate(std::string_view mnemonic) {
  const auto it = Table().find(Lower(mnemonic));
  if (it == Table().end()) return false;
  const std::string& ops = it->second.operands;
  return !Has(ops, "t") && (ops.find(",b") != std::string::npos);
}

}  // namespace xpulp_asm
