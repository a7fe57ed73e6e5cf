// The cluster DMA: one engine serving transfers in order, L2 <-> L1, 1-D or 2-D (strided on
// the L2 side, contiguous in L1, as GAP8's cluster DMA). Bytes move when a transfer completes.
#pragma once

#include <cstdint>
#include <deque>
#include <string>

#include "gap8/memory.h"

namespace gap8 {

struct DmaCommand {
  uint32_t ext = 0;     // L2 address
  uint32_t loc = 0;     // L1 address
  uint32_t size = 0;    // total bytes
  uint32_t dir = 0;     // 0: L1 -> L2, 1: L2 -> L1
  uint32_t stride = 0;  // 2-D: L2 bytes between row starts
  uint32_t length = 0;  // 2-D: bytes per row; 0 for a 1-D transfer
};

class Dma {
 public:
  // Why the command cannot run (empty when it can): a range outside L1 or L2, a zero size...
  static std::string Check(const DmaCommand& cmd);
  // Queues a checked command issued at cycle `now`; returns its id (ids start at 1).
  uint32_t Push(const DmaCommand& cmd, uint64_t now);
  bool Done(uint32_t id) const { return id <= completed_; }
  bool Idle() const { return queue_.empty(); }
  // Cycle at which the oldest queued transfer completes (meaningless when Idle()).
  uint64_t NextCompletion() const { return queue_.front().done_at; }
  // Moves the oldest transfer's bytes and returns its id.
  uint32_t CompleteNext(Memory& memory);

 private:
  struct Transfer {
    DmaCommand cmd;
    uint32_t id;
    uint64_t done_at;
  };
  std::deque<Transfer> queue_;
  uint64_t busy_until_ = 0;
  uint32_t next_id_ = 1;
  uint32_t completed_ = 0;
};

}  // namespace gap8
