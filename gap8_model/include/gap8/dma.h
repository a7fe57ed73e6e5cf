// The cluster DMA (mchan v6) as GVSOC models it (gap_sdk gvsoc/gvsoc_gap/models/pulp/mchan/
// mchan_v6_impl.cpp; costs in timing.h). L2 <-> L1, 1-D or 2-D (strided on the L2 side,
// contiguous in L1). A command is cut into bursts of at most 256 bytes (2-D: within a row), sent
// one per cycle; GVSOC's L2 side answers at once, so the TCDM side sets the pace: each direction
// has two ports writing (or reading) one aligned word piece of a burst per cycle. Every piece
// takes its TCDM bank for that cycle (BanksAt). A transfer completes with its last piece; its
// bytes move then, so reading the destination earlier sees the old data.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

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
  struct Completion {
    uint32_t counter;
    uint32_t core;  // the core that queued it
    bool event, broadcast;
  };

  // Why the command cannot run (empty when it can): a range outside L1 or L2, a zero size...
  static std::string Check(const DmaCommand& cmd);
  // Queues a checked command whose last word was written at cycle `now`, on `counter`.
  void Push(const DmaCommand& cmd, uint64_t now, uint32_t counter, uint32_t core, bool event,
            bool broadcast);
  bool Idle() const { return queue_.empty(); }
  // Cycle at which the earliest queued transfer completes (meaningless when Idle()).
  uint64_t NextCompletion() const { return queue_[next_].done_at; }
  // Moves the bytes of the transfer completing first and says whose it was.
  Completion CompleteNext(Memory& memory);
  // Transfers queued and not complete on `counter`.
  uint32_t Pending(uint32_t counter) const { return pending_[counter]; }

  // TCDM banks (bit per bank) the DMA's pieces take at `cycle`; 0 outside its traffic.
  uint32_t BanksAt(uint64_t cycle) const {
    const uint64_t i = cycle - banks_base_;
    return i < banks_size_ ? banks_[i] : 0u;
  }
  // First cycle after the last one in which the DMA takes a bank.
  uint64_t BankTrafficEnd() const { return banks_base_ + banks_size_; }

 private:
  struct Transfer {
    DmaCommand cmd;
    uint64_t done_at;
    Completion who;
  };
  // One direction's TCDM ports: the cycle whose port slots are being filled and how many are.
  struct LocalStream {
    uint64_t cycle = 0;
    uint32_t used = 0;
    uint64_t next_burst = 0;  // first cycle the next burst may be sent
  };
  // Schedules the pieces of one burst of `bytes` at L1 address `loc`, available from cycle
  // `from`; returns the cycle of its last piece.
  uint64_t ScheduleBurst(LocalStream& s, uint32_t loc, uint32_t bytes, uint64_t from);
  void TakeBank(uint64_t cycle, uint32_t addr);
  void PickNext();

  std::vector<Transfer> queue_;  // transfers not complete, in push order
  size_t next_ = 0;              // index of the one completing first
  LocalStream to_l1_, to_l2_;
  std::deque<uint16_t> banks_;  // bank mask per cycle from banks_base_
  uint64_t banks_base_ = 0;
  uint64_t banks_size_ = 0;  // banks_.size(), which a deque computes: read every cycle
  std::vector<uint32_t> pending_ = std::vector<uint32_t>(16, 0);
};

}  // namespace gap8
