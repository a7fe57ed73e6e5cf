// The timing rules of include/gap8/timing.h against values derived by hand from their sources
// (GVSOC in gap_sdk: mchan_v6_impl.cpp, cache_impl.cpp, rv32m.hpp; docs/gap8-model.md).
#include <catch2/catch.hpp>

#include "gap8/dma.h"
#include "gap8/icache.h"
#include "gap8/timing.h"

namespace {

constexpr bool kEvent = true, kBroadcast = true;

gap8::DmaCommand ToL1(uint32_t loc_offset, uint32_t size, uint32_t stride = 0,
                      uint32_t length = 0) {
  return {GAP8_L2_BASE, GAP8_L1_BASE + loc_offset, size, 1, stride, length};
}

uint32_t Bank(uint32_t word) { return 1u << (word % GAP8_L1_BANKS); }

}  // namespace

TEST_CASE("timing constants are the sources' numbers") {
  using namespace gap8::timing;
  CHECK(kL2Latency == 8u);                // soc_gen.py: ll_ico 'l2' mapping latency
  CHECK(kIcacheRefill == 8u + 16u / 4u);  // + a 16-byte line on a 4-byte/cycle router
  CHECK(kIcacheSets * kIcacheWays * kIcacheLineBytes == 4096u);  // gap8_revc.json: 4 KiB
  CHECK(kWakeUp == 1u + 6u);                             // eu_v3: EU_WAKEUP_REQ_LATENCY, core's + 1
  CHECK(kEuWaitLatency + kEuNoSleepLatency == 6u + 2u);  // + EU_WAKEUP_LATENCY
  CHECK(kDmaMaxBurst == 256u);                           // mchan_v6.json max_burst_length
}

// RI5CY RTL (riscv_alu.sv div_shift, riscv_alu_div.sv: div_shift + 3) and the CV32E40P manual
// (3..35); the cases where GVSOC's clz(-d) + 2 differs are marked.
TEST_CASE("divider: the RTL's leading-bit count + 3 (RI5CY riscv_alu_div, CV32E40P manual)") {
  using gap8::timing::Divide;
  CHECK(Divide(1, true) == 34u);
  CHECK(Divide(1, false) == 34u);
  CHECK(Divide(256, false) == 26u);
  CHECK(Divide(0x80000000u, false) == 3u);  // no leading zero: the manual's minimum
  CHECK(Divide(0, true) == 35u);            // the manual's maximum
  CHECK(Divide(0, false) == 35u);
  CHECK(Divide(static_cast<uint32_t>(-1), false) == 3u);  // unsigned 0xFFFFFFFF
  CHECK(Divide(static_cast<uint32_t>(-3), true) == 32u);  // 30 leading ones: GVSOC agrees
  // Negative powers of two: GVSOC gives one cycle less (33, 32, 2).
  CHECK(Divide(static_cast<uint32_t>(-1), true) == 34u);  // no one in ~d: 31 + 3
  CHECK(Divide(static_cast<uint32_t>(-2), true) == 33u);  // 31 leading ones
  CHECK(Divide(0x80000000u, true) == 3u);                 // -2^31: 1 leading one
}

// mchan_v6: last command word at t; queue move t+1; first burst sent t+2; its pieces from
// t+3, two 32-bit pieces a cycle. An aligned N-byte 1-D transfer (bursts of 256 drain slower
// than they are sent) completes at t + 2 + ceil(N / 8).
TEST_CASE("DMA L2 -> L1, 1-D: completes at push + 2 + ceil(bytes / 8), in push order") {
  gap8::Memory memory;
  gap8::Dma dma;
  uint8_t src[64];
  for (int i = 0; i < 64; ++i) src[i] = static_cast<uint8_t>(i + 1);
  memory.Write(GAP8_L2_BASE, src, 64);
  dma.Push(ToL1(0, 64), 100, 3, 0, kEvent, kBroadcast);
  CHECK(dma.NextCompletion() == 100u + 2u + 64u / 8u);
  CHECK(dma.Pending(3) == 1u);
  // The 16 words go to banks 0,1 at cycle 103, 2,3 at 104, ... 14,15 at 110.
  CHECK(dma.BanksAt(102) == 0u);
  CHECK(dma.BanksAt(103) == (Bank(0) | Bank(1)));
  CHECK(dma.BanksAt(110) == (Bank(14) | Bank(15)));
  const gap8::Dma::Completion done = dma.CompleteNext(memory);
  CHECK(done.counter == 3u);
  CHECK(done.event);
  CHECK(dma.Pending(3) == 0u);
  CHECK(dma.Idle());
  uint8_t l1[64];
  memory.Read(GAP8_L1_BASE, l1, 64);
  CHECK(l1[0] == 1);
  CHECK(l1[63] == 64);

  gap8::Dma big;  // a 64x64 frame: 16 bursts of 256 bytes, 1024 pieces, 512 cycles
  big.Push(ToL1(0, 4096), 0, 0, 0, kEvent, kBroadcast);
  CHECK(big.NextCompletion() == 2u + 4096u / 8u);
}

TEST_CASE("DMA pieces end at 32-bit boundaries: a second transfer follows the first") {
  gap8::Dma dma;
  // 8 bytes at L1 + 2: pieces of 2, 4 and 2 bytes -> cycles 3, 3, 4.
  dma.Push(ToL1(2, 8), 0, 0, 0, kEvent, kBroadcast);
  CHECK(dma.NextCompletion() == 4u);
  CHECK(dma.BanksAt(3) == (Bank(0) | Bank(1)));
  CHECK(dma.BanksAt(4) == Bank(2));
  // Pushed at the same cycle: its burst goes out at 3 (after the first's), pieces at 4 (the
  // second port that cycle), then 5.
  dma.Push(ToL1(64, 8), 0, 1, 0, kEvent, kBroadcast);
  gap8::Memory memory;
  CHECK(dma.CompleteNext(memory).counter == 0u);
  CHECK(dma.NextCompletion() == 5u);
  CHECK(dma.BanksAt(4) == (Bank(2) | Bank(16)));
}

TEST_CASE("DMA 2-D: one burst per row and cycle, so short rows are paced by the bursts") {
  gap8::Dma dma;
  // 4 rows of 4 bytes, 64 apart in L2: bursts at 2, 3, 4, 5; one piece each at 3, 4, 5, 6.
  dma.Push(ToL1(0, 16, 64, 4), 0, 0, 0, kEvent, kBroadcast);
  CHECK(dma.NextCompletion() == 6u);
  CHECK(dma.BanksAt(6) == Bank(3));
  gap8::Dma wide;  // 2 rows of 512 bytes: bursts of 256 within a row, 128 cycles of pieces
  wide.Push(ToL1(0, 1024, 2048, 512), 10, 0, 0, kEvent, kBroadcast);
  CHECK(wide.NextCompletion() == 10u + 2u + 1024u / 8u);
}

// L1 -> L2: mchan_v6 reads one burst from TCDM at a time (pending_loc_read_req); after its last
// piece at c, the burst is sent on and the next one is prepared at c + 1, read from c + 2.
TEST_CASE("DMA L1 -> L2: a cycle of gap between bursts") {
  gap8::Dma dma;
  gap8::DmaCommand out{GAP8_L2_BASE, GAP8_L1_BASE, 512, 0, 0, 0};
  dma.Push(out, 0, 0, 0, kEvent, kBroadcast);
  // burst 0: cycles 3..34; burst 1: 36..67.
  CHECK(dma.NextCompletion() == 67u);
  CHECK(dma.BanksAt(35) == 0u);
  CHECK(dma.BanksAt(36) == (Bank(0) | Bank(1)));  // word 64 is in bank 0
}

TEST_CASE("icache: miss 12 cycles, one refill at a time, hit under refill waits for it") {
  gap8::ICache cache;
  const uint32_t a = GAP8_L2_BASE, b = GAP8_L2_BASE + 16;
  const uint32_t refill = gap8::timing::kIcacheRefill;
  CHECK(cache.Access(a, 100, refill) == 12u);
  CHECK(cache.Access(b, 100, refill) == 24u);  // waits for a's refill (done at 112)
  CHECK(cache.Access(a, 105, refill) == 7u);   // hit, line ready at 112
  CHECK(cache.Access(b, 124, refill) == 0u);
  CHECK(cache.Access(a, 500, refill) == 0u);
  CHECK(cache.refills() == 2u);
}

// GVSOC Cache::stepLru from 0: 1, 3, 6, 13, 27 -> victim ways (value >> 1) & 3 = 0, 1, 3, 2, 1.
TEST_CASE("icache: replacement follows GVSOC's 8-bit LFSR, not LRU") {
  gap8::ICache cache;
  const uint32_t set_stride = gap8::timing::kIcacheSets * gap8::timing::kIcacheLineBytes;
  auto line = [&](int i) { return GAP8_L2_BASE + static_cast<uint32_t>(i) * set_stride; };
  uint64_t t = 0;
  for (int i = 0; i < 4; ++i) CHECK(cache.Access(line(i), t += 100, 12) == 12u);  // ways 0 1 3 2
  for (int i = 0; i < 4; ++i) CHECK(cache.Access(line(i), t += 100, 12) == 0u);
  CHECK(cache.Access(line(4), t += 100, 12) == 12u);  // evicts way 1: line 1
  CHECK(cache.Access(line(0), t += 100, 12) == 0u);
  CHECK(cache.Access(line(2), t += 100, 12) == 0u);
  CHECK(cache.Access(line(3), t += 100, 12) == 0u);
  CHECK(cache.Access(line(1), t += 100, 12) == 12u);
}
