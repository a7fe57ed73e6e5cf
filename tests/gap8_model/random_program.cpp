#include "random_program.h"

#include "gap8/decoded.h"

namespace {

// Registers that hold data addresses and are never written: sp (c.lwsp/c.swsp), s0 and s1
// (the compressed loads' and stores' register set includes them).
constexpr uint32_t kBaseRegs[] = {2, 8, 9};

bool IsBase(uint32_t r) { return r == 2 || r == 8 || r == 9; }

bool IsMemory(gap8::Op op) { return op == gap8::Op::kLoad || op == gap8::Op::kStore; }

bool WritesRd(gap8::Op op) { return op != gap8::Op::kStore && op != gap8::Op::kFence; }

// Straight-line instructions only; control flow is generated with known targets.
bool Acceptable(const gap8::Decoded& d) {
  using gap8::Op;
  if (d.op == Op::kIllegal || d.op == Op::kUndecoded) return false;
  if (IsXpulp(d.op)) return false;  // Unicorn does not know Xpulp
  if ((d.op >= Op::kJal && d.op <= Op::kBgeu)) return false;
  if (WritesRd(d.op) && IsBase(d.rd)) return false;
  if (IsMemory(d.op) && !IsBase(d.rs1)) return false;
  return true;
}

uint32_t RandomWide(std::mt19937& rng) {
  static constexpr uint32_t kOpcodes[] = {0x13, 0x13, 0x33, 0x33, 0x33, 0x37, 0x17, 0x03, 0x23};
  uint32_t w = rng();
  const uint32_t opcode = kOpcodes[rng() % std::size(kOpcodes)];
  w = (w & ~0x7Fu) | opcode;
  if (opcode == 0x33) {  // OP: base, alternate (sub/sra) or M extension
    static constexpr uint32_t kFunct7[] = {0x00, 0x20, 0x01};
    w = (w & 0x01FFFFFFu) | (kFunct7[rng() % 3] << 25);
  }
  if (opcode == 0x03 || opcode == 0x23) w = (w & ~(0x1Fu << 15)) | (kBaseRegs[rng() % 3] << 15);
  return w;
}

enum class Kind { kPlain32, kPlain16, kBranch, kJal, kCj, kCbz, kAuipcJalr };

struct Slot {
  Kind kind;
  uint32_t bits = 0;  // kPlain*: the encoding; otherwise registers/condition packed below
  uint32_t rs1 = 0, rs2 = 0, rd = 0, cond = 0;
  int target = 0;  // index of the target slot (== count: the end)
  uint32_t size = 4;
};

uint32_t NonBaseReg(std::mt19937& rng) {
  for (;;) {
    uint32_t r = rng() % 32;
    if (!IsBase(r)) return r;
  }
}

Slot RandomStraight(std::mt19937& rng) {
  for (;;) {
    const bool compressed = rng() % 3 == 0;
    const uint32_t bits = compressed ? rng() & 0xFFFFu : RandomWide(rng);
    if (compressed && (bits & 3u) == 3u) continue;
    if (Acceptable(gap8::Decode(bits))) {
      return Slot{
          compressed ? Kind::kPlain16 : Kind::kPlain32, bits, 0, 0, 0, 0, 0, compressed ? 2u : 4u};
    }
  }
}

Slot RandomControl(std::mt19937& rng, int index, int count) {
  Slot s{};
  s.kind = static_cast<Kind>(2 + rng() % 5);
  s.target = index + 1 + static_cast<int>(rng() % 6);
  if (s.target > count) s.target = count;
  static constexpr uint32_t kConds[] = {0, 1, 4, 5, 6, 7};
  s.cond = kConds[rng() % 6];
  s.rs1 = rng() % 32;
  s.rs2 = rng() % 32;
  s.rd = NonBaseReg(rng);
  s.size = (s.kind == Kind::kCj || s.kind == Kind::kCbz) ? 2 : s.kind == Kind::kAuipcJalr ? 8 : 4;
  if (s.kind == Kind::kCbz) s.rs1 = 10 + rng() % 6;
  if (s.kind == Kind::kAuipcJalr && s.rd == 0) s.rd = 5;  // the temporary must be a real register
  return s;
}

uint32_t Bit(uint32_t v, int b) { return (v >> b) & 1u; }
uint32_t Field(uint32_t v, int hi, int lo) { return (v >> lo) & ((1u << (hi - lo + 1)) - 1); }

uint32_t EncodeBranch(const Slot& s, uint32_t off) {
  return (Bit(off, 12) << 31) | (Field(off, 10, 5) << 25) | (s.rs2 << 20) | (s.rs1 << 15) |
         (s.cond << 12) | (Field(off, 4, 1) << 8) | (Bit(off, 11) << 7) | 0x63;
}
uint32_t EncodeJal(uint32_t rd, uint32_t off) {
  return (Bit(off, 20) << 31) | (Field(off, 10, 1) << 21) | (Bit(off, 11) << 20) |
         (Field(off, 19, 12) << 12) | (rd << 7) | 0x6F;
}
uint32_t EncodeCj(uint32_t off) {
  return (0x5u << 13) | (Bit(off, 11) << 12) | (Bit(off, 4) << 11) | (Field(off, 9, 8) << 9) |
         (Bit(off, 10) << 8) | (Bit(off, 6) << 7) | (Bit(off, 7) << 6) | (Field(off, 3, 1) << 3) |
         (Bit(off, 5) << 2) | 0x1;
}
uint32_t EncodeCbz(const Slot& s, uint32_t off) {
  const uint32_t funct3 = (s.cond & 1) ? 0x7u : 0x6u;  // c.bnez / c.beqz
  return (funct3 << 13) | (Bit(off, 8) << 12) | (Field(off, 4, 3) << 10) | ((s.rs1 - 8) << 7) |
         (Field(off, 7, 6) << 5) | (Field(off, 2, 1) << 3) | (Bit(off, 5) << 2) | 0x1;
}

void Emit(std::vector<uint8_t>& code, uint32_t bits, uint32_t size) {
  for (uint32_t i = 0; i < size; ++i) code.push_back(static_cast<uint8_t>(bits >> (8 * i)));
}

void EmitSlot(std::vector<uint8_t>& code, const Slot& s, uint32_t addr, uint32_t target) {
  const uint32_t off = target - addr;
  switch (s.kind) {
    case Kind::kPlain32:
    case Kind::kPlain16:
      return Emit(code, s.bits, s.size);
    case Kind::kBranch:
      return Emit(code, EncodeBranch(s, off), 4);
    case Kind::kJal:
      return Emit(code, EncodeJal(s.rd, off), 4);
    case Kind::kCj:
      return Emit(code, EncodeCj(off), 2);
    case Kind::kCbz:
      return Emit(code, EncodeCbz(s, off), 2);
    case Kind::kAuipcJalr:
      Emit(code, (s.rd << 7) | 0x17, 4);                                      // auipc rd, 0
      return Emit(code, (off << 20) | (s.rd << 15) | (s.rd << 7) | 0x67, 4);  // jalr rd, off(rd)
  }
}

uint32_t InterestingValue(std::mt19937& rng) {
  static constexpr uint32_t kValues[] = {0, 1, 2, 0xFFFFFFFFu, 0x80000000u, 0x7FFFFFFFu, 31, 32};
  return rng() % 3 == 0 ? kValues[rng() % std::size(kValues)] : static_cast<uint32_t>(rng());
}

}  // namespace

RandomProgram MakeRandomProgram(std::mt19937& rng, int instructions, uint32_t code_base) {
  std::vector<Slot> slots;
  for (int i = 0; i < instructions; ++i)
    slots.push_back(rng() % 8 == 0 ? RandomControl(rng, i, instructions) : RandomStraight(rng));
  std::vector<uint32_t> addr(slots.size() + 1, code_base);
  for (size_t i = 0; i < slots.size(); ++i) addr[i + 1] = addr[i] + slots[i].size;
  RandomProgram p;
  p.start = code_base;
  p.end = addr.back();
  for (size_t i = 0; i < slots.size(); ++i)
    EmitSlot(p.code, slots[i], addr[i], addr[slots[i].target]);
  for (int r = 1; r < 32; ++r) p.regs[r] = InterestingValue(rng);
  p.regs[2] = kRandomDataBase + 0x1000 + 4 * (rng() % 64);
  p.regs[8] = kRandomDataBase + 0x2000 + 4 * (rng() % 64);
  p.regs[9] = kRandomDataBase + 0x3000 + 4 * (rng() % 64);
  p.data.resize(kRandomDataSize);
  for (auto& b : p.data) b = static_cast<uint8_t>(rng());
  return p;
}
