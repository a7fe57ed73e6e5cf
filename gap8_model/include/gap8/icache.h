// The cluster's shared instruction cache, as GVSOC models it (gap_sdk gvsoc/gvsoc/models/cache/
// cache_impl.cpp, geometry from gap8_revc.json; costs in timing.h): 64 sets x 4 ways of 16-byte
// lines, tag = the whole line address, replacement by the 8-bit LFSR GVSOC uses for GAP's
// caches (stepped once per refill, whatever the set), one refill at a time. Only timing is
// modelled: the bytes always come from memory.
#pragma once

#include <array>
#include <cstdint>

#include "gap8/timing.h"

namespace gap8 {

class ICache {
 public:
  ICache() { Reset(); }
  void Reset();

  // Cycles a core waits for the line at line_addr (16-byte aligned) requested at cycle now: 0 on
  // a hit whose refill is over, the rest of the refill on a hit whose refill is under way, the
  // wait for the refill in progress plus its own refill on a miss. refill_cycles: what one
  // refill costs from where the line lives (timing.h).
  uint32_t Access(uint32_t line_addr, uint64_t now, uint32_t refill_cycles) {
    const uint32_t tag = line_addr / timing::kIcacheLineBytes;
    const uint32_t set = tag & (timing::kIcacheSets - 1);
    for (uint32_t way = 0; way < timing::kIcacheWays; ++way) {
      if (tags_[set][way] == tag) {
        const uint64_t ready = ready_at_[set][way];
        return ready > now ? static_cast<uint32_t>(ready - now) : 0;
      }
    }
    return Refill(set, tag, now, refill_cycles);
  }

  uint64_t refills() const { return refills_; }

 private:
  // GVSOC Cache::stepLru: feedback = !(b7 ^ b3 ^ b2 ^ b1), way = bits 2..1 of the new value.
  uint32_t NextVictimWay() {
    const uint32_t s = lfsr_;
    const uint32_t feedback = ~((s >> 7) ^ (s >> 3) ^ (s >> 2) ^ (s >> 1)) & 1u;
    lfsr_ = static_cast<uint8_t>((s << 1) | feedback);
    return (lfsr_ >> 1) & (timing::kIcacheWays - 1);
  }

  // A miss: the host's slow path (inline above is only the hit test, run every few
  // instructions).
  uint32_t Refill(uint32_t set, uint32_t tag, uint64_t now, uint32_t refill_cycles);

  // Per set and way: the line's tag, and the cycle its refill completes.
  std::array<std::array<uint32_t, timing::kIcacheWays>, timing::kIcacheSets> tags_;
  std::array<std::array<uint64_t, timing::kIcacheWays>, timing::kIcacheSets> ready_at_;
  uint8_t lfsr_ = 0;
  uint64_t refill_done_ = 0;  // cycle the refill in progress (if any) completes
  uint64_t refills_ = 0;
};

}  // namespace gap8
