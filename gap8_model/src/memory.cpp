#include "gap8/memory.h"

#include <new>
#include <type_traits>

namespace gap8 {

namespace {
constexpr uint32_t kPad = 4;  // lets a fetch at the last half-word read 32 bits safely
}

Memory::Memory()
    : l1_(GAP8_L1_SIZE + kPad),
      l2_(GAP8_L2_SIZE + kPad),
      l1_code_(ZeroedSlots(GAP8_L1_SIZE / 2)),
      l2_code_(ZeroedSlots(GAP8_L2_SIZE / 2)) {}

Memory::CodeSlots Memory::ZeroedSlots(size_t count) {
  static_assert(std::is_trivially_copyable_v<Decoded> && Op::kUndecoded == Op{});
  auto* slots = static_cast<Decoded*>(std::calloc(count, sizeof(Decoded)));
  if (slots == nullptr) throw std::bad_alloc();
  return CodeSlots(slots);
}

uint32_t Memory::FetchBits(uint32_t pc) {
  uint8_t* p = Span(pc, 2);
  uint32_t bits = 0;
  if (p) std::memcpy(&bits, p, 4);
  return bits;
}

void Memory::InvalidateCodeSlow(uint32_t addr, uint32_t size) {
  // A 32-bit instruction starting 2 bytes before addr also overlaps the write.
  const uint32_t first = addr - 2;
  for (uint32_t a = first & ~1u; a - first < size + 2; a += 2) {
    if (Decoded* slot = CodeSlot(a)) slot->op = Op::kUndecoded;
  }
}

bool Memory::Write(uint32_t addr, const void* src, uint32_t size) {
  uint8_t* p = Span(addr, size);
  if (!p) return false;
  std::memcpy(p, src, size);
  InvalidateCode(addr, size);
  return true;
}

bool Memory::Read(uint32_t addr, void* dst, uint32_t size) {
  uint8_t* p = Span(addr, size);
  if (!p) return false;
  std::memcpy(dst, p, size);
  return true;
}

}  // namespace gap8
