// The cluster's memories (L1 TCDM, L2) with a decode cache beside each, so an instruction is
// decoded once however often it runs. Peripherals are not here: the Cluster serves them.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "../../runtime/gap8_regs.h"
#include "gap8/decoded.h"

namespace gap8 {

class Memory {
 public:
  Memory();

  // Host pointer to [addr, addr + size) when it lies wholly in L1 or L2, else nullptr.
  uint8_t* L1Span(uint32_t addr, uint32_t size) {
    const uint32_t off = addr - GAP8_L1_BASE;
    return (off < GAP8_L1_SIZE && size <= GAP8_L1_SIZE - off) ? l1_.data() + off : nullptr;
  }
  uint8_t* L2Span(uint32_t addr, uint32_t size) {
    const uint32_t off = addr - GAP8_L2_BASE;
    return (off < GAP8_L2_SIZE && size <= GAP8_L2_SIZE - off) ? l2_.data() + off : nullptr;
  }
  uint8_t* Span(uint32_t addr, uint32_t size) {
    uint8_t* p = L1Span(addr, size);
    return p ? p : L2Span(addr, size);
  }

  static bool InL2(uint32_t addr) { return addr - GAP8_L2_BASE < GAP8_L2_SIZE; }
  // Decode-cache slot for the instruction at pc, which InL2.
  Decoded* L2CodeSlot(uint32_t pc) { return &l2_code_[(pc - GAP8_L2_BASE) >> 1]; }
  // Decode-cache slot for the instruction at pc, or nullptr when pc is not in L1 or L2.
  Decoded* CodeSlot(uint32_t pc) {
    uint32_t off = pc - GAP8_L2_BASE;
    if (off < GAP8_L2_SIZE) return &l2_code_[off >> 1];
    off = pc - GAP8_L1_BASE;
    if (off < GAP8_L1_SIZE) {
      l1_has_code_ = true;
      return &l1_code_[off >> 1];
    }
    return nullptr;
  }

  // 32 bits from pc (the memories carry 4 bytes of zero padding past their end).
  uint32_t FetchBits(uint32_t pc);

  // False until an instruction in L1 was decoded: stores to L1 cannot rewrite code before.
  bool l1_has_code() const { return l1_has_code_; }

  // Forgets decoded instructions overlapping [addr, addr + size): the bytes were rewritten.
  void InvalidateCode(uint32_t addr, uint32_t size) {
    // Data stores are frequent and code in L1 is rare: skip L1 until code was decoded there.
    if (!l1_has_code_ && addr - GAP8_L1_BASE < GAP8_L1_SIZE) return;
    InvalidateCodeSlow(addr, size);
  }

  // Copies host bytes in (ELF loading, tests); false when the range is not wholly mapped.
  bool Write(uint32_t addr, const void* src, uint32_t size);
  bool Read(uint32_t addr, void* dst, uint32_t size);

 private:
  void InvalidateCodeSlow(uint32_t addr, uint32_t size);

  // The decode caches, a slot per half-word: 9 MB, of which a program touches a few pages.
  // calloc'd, so the host maps zero pages only where a slot is read or written (a vector of
  // Decoded{} writes them all: 2,300 more page faults, 5 ms of host time per run on the Zen 4
  // VM of docs/measurements/gap8-model-host-speed.md). An all-zero slot is undecoded
  // (Op::kUndecoded is 0; its other fields are never read).
  struct FreeDeleter {
    void operator()(Decoded* p) const { std::free(p); }
  };
  using CodeSlots = std::unique_ptr<Decoded[], FreeDeleter>;
  static CodeSlots ZeroedSlots(size_t count);

  std::vector<uint8_t> l1_, l2_;
  bool l1_has_code_ = false;
  CodeSlots l1_code_, l2_code_;
};

}  // namespace gap8
