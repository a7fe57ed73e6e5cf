#include "gap8/dma.h"

#include <algorithm>
#include <vector>

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
  if (c.size == 0) return "DMA transfer of 0 bytes";
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

uint32_t Dma::Push(const DmaCommand& cmd, uint64_t now) {
  const uint64_t start = std::max(now, busy_until_);
  uint64_t cost =
      timing::kDmaSetup + (cmd.size + timing::kDmaBytesPerCycle - 1) / timing::kDmaBytesPerCycle;
  if (cmd.length != 0) cost += static_cast<uint64_t>(Rows(cmd)) * timing::kDmaRowSetup;
  busy_until_ = start + cost;
  queue_.push_back({cmd, next_id_, busy_until_});
  return next_id_++;
}

uint32_t Dma::CompleteNext(Memory& memory) {
  const Transfer t = queue_.front();
  queue_.pop_front();
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
  completed_ = t.id;
  return t.id;
}

}  // namespace gap8
