#include "gap8/icache.h"

namespace gap8 {

namespace {
constexpr uint32_t kNoTag = ~0u;  // no line address shifted right by 4 reaches it
}

void ICache::Reset() {
  for (auto& set : tags_) set.fill(kNoTag);
  for (auto& set : ready_at_) set.fill(0);
  lfsr_ = 0;
  refill_done_ = 0;
  refills_ = 0;
}

uint32_t ICache::Refill(uint32_t set, uint32_t tag, uint64_t now, uint32_t refill_cycles) {
  // GVSOC sets the tag at once and answers when the refill is over; a refill still under way for
  // another line delays this one.
  const uint64_t start = refill_done_ > now ? refill_done_ : now;
  const uint64_t done = start + refill_cycles;
  const uint32_t way = NextVictimWay();
  tags_[set][way] = tag;
  ready_at_[set][way] = done;
  refill_done_ = done;
  ++refills_;
  return static_cast<uint32_t>(done - now);
}

}  // namespace gap8
