#include "gap8/dma.h"

#include <algorithm>

#include "gap8/fault.h"
#include "gap8/timing.h"

namespace gap8 {
namespace {

uint32_t RowLength(const DmaCommand& c) { return c.length == 0 ? c.size : c.length; }
uint32_t Rows(const DmaCommand& c) { return (c.size + RowLength(c) - 1) / RowLength(c); }

bool InL1(uint32_t addr, uint64_t size) {
  return addr >= GAP8_L1_BASE && addr - GAP8_L1_BASE + size <= GAP8_L1_SIZE;
}
bool InL2(uint32_t addr, uint64_t size) {
  return addr >= GAP8_L2_BASE && addr - GAP8_L2_BASE + size <= GAP8_L2_SIZE;
}

}  // namespace

std::string Dma::Check(const DmaCommand& c) {
  if (c.size == 0) return "DMA transfer of 0 bytes (mchan sizes are 1..65535)";
  if (c.dir > 1) return "DMA direction " + std::to_string(c.dir) + " is neither 0 nor 1";
  if (!InL1(c.loc, c.size))
    return "DMA L1 range " + Hex(c.loc) + " + " + std::to_string(c.size) + " bytes is outside L1";
  if (c.length != 0 && c.stride < c.length) return "DMA 2-D stride smaller than the row length";
  // L2 bytes touched: every row but the last is `length` long, rows start `stride` apart.
  const uint64_t rows = Rows(c);
  const uint64_t stride = c.length == 0 ? 0 : c.stride;
  const uint64_t span = (rows - 1) * stride + (c.size - (rows - 1) * RowLength(c));
  if (!InL2(c.ext, span)) return "DMA L2 range " + Hex(c.ext) + " is outside L2";
  return "";
}

void Dma::TakeBank(uint64_t cycle, uint32_t addr) {
  if (banks_.empty()) banks_base_ = cycle;
  if (cycle < banks_base_) {  // the other direction's stream started later: grow to the front
    banks_.insert(banks_.begin(), banks_base_ - cycle, 0);
    banks_base_ = cycle;
  }
  const uint64_t i = cycle - banks_base_;
  if (i >= banks_.size()) banks_.resize(i + 1, 0);
  banks_[i] |= static_cast<uint16_t>(1u << ((addr >> 2) & (GAP8_L1_BANKS - 1)));
  banks_size_ = banks_.size();
}

// mchan_v6 check_loc_transfer_handler: a piece ends at the next 32-bit boundary or the burst's
// end; ports take pieces in order, kDmaLocalPorts a cycle.
uint64_t Dma::ScheduleBurst(LocalStream& s, uint32_t loc, uint32_t bytes, uint64_t from) {
  if (s.cycle < from) {
    s.cycle = from;
    s.used = 0;
  }
  while (bytes != 0) {
    if (s.used == timing::kDmaLocalPorts) {
      ++s.cycle;
      s.used = 0;
    }
    const uint32_t piece =
        std::min(bytes, timing::kDmaLocalPortBytes - (loc & (timing::kDmaLocalPortBytes - 1)));
    TakeBank(s.cycle, loc);
    ++s.used;
    loc += piece;
    bytes -= piece;
  }
  return s.cycle;
}

void Dma::Push(const DmaCommand& cmd, uint64_t now, uint32_t counter, uint32_t core, bool event,
               bool broadcast) {
  // The command reaches the global queue a cycle after its last word and its first burst goes
  // out the cycle after (kDmaFirstBurst); bursts leave one a cycle. L2 -> L1: a burst's pieces
  // are written from the cycle after it is sent. L1 -> L2: the next burst is read from TCDM only
  // once the previous one is sent on (send_loc_read_req waits for pending_loc_read_req), two
  // cycles after its last piece.
  LocalStream& s = cmd.dir == 1 ? to_l1_ : to_l2_;
  uint64_t burst_at = std::max(now + timing::kDmaFirstBurst, s.next_burst);
  uint64_t last = burst_at;
  uint32_t loc = cmd.loc;
  for (uint32_t done = 0; done < cmd.size;) {
    const uint32_t row_left = RowLength(cmd) - done % RowLength(cmd);
    const uint32_t bytes = std::min({timing::kDmaMaxBurst, row_left, cmd.size - done});
    last = ScheduleBurst(s, loc, bytes, burst_at + 1);
    burst_at = cmd.dir == 1 ? burst_at + 1 : last + 1;
    loc += bytes;
    done += bytes;
  }
  s.next_burst = burst_at;
  queue_.push_back({cmd, last, {counter, core, event, broadcast}});
  ++pending_[counter];
  PickNext();
}

void Dma::PickNext() {
  next_ = 0;
  for (size_t i = 1; i < queue_.size(); ++i) {
    if (queue_[i].done_at < queue_[next_].done_at) next_ = i;
  }
}

Dma::Completion Dma::CompleteNext(Memory& memory) {
  const Transfer t = queue_[next_];
  queue_.erase(queue_.begin() + static_cast<std::ptrdiff_t>(next_));
  const DmaCommand& c = t.cmd;
  std::vector<uint8_t> row;
  for (uint32_t done = 0, r = 0; done < c.size; ++r) {
    const uint32_t n = std::min(RowLength(c), c.size - done);
    const uint32_t ext = c.ext + r * (c.length == 0 ? 0 : c.stride);
    const uint32_t loc = c.loc + done;
    row.resize(n);
    // Ranges were checked at push time, so these copies cannot fail.
    if (c.dir == 1) {
      memory.Read(ext, row.data(), n);
      memory.Write(loc, row.data(), n);
    } else {
      memory.Read(loc, row.data(), n);
      memory.Write(ext, row.data(), n);
    }
    done += n;
  }
  --pending_[t.who.counter];
  // No core issues before this completion any more: forget the bank map up to it.
  if (queue_.empty()) {
    banks_.clear();
  } else {
    const uint64_t drop =
        std::min<uint64_t>(t.done_at - std::min(t.done_at, banks_base_), banks_.size());
    banks_.erase(banks_.begin(), banks_.begin() + static_cast<std::ptrdiff_t>(drop));
    banks_base_ += drop;
    PickNext();
  }
  banks_size_ = banks_.size();
  return t.who;
}

}  // namespace gap8
