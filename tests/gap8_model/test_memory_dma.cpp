// DMA command checks and the cost functions of the timing table.
#include <catch2/catch.hpp>

#include "gap8/dma.h"
#include "gap8/timing.h"

TEST_CASE("DMA commands outside L1 or L2 are refused with a reason") {
  gap8::DmaCommand ok{GAP8_L2_BASE, GAP8_L1_BASE, 256, 1, 0, 0};
  CHECK(gap8::Dma::Check(ok).empty());
  gap8::DmaCommand c = ok;
  c.size = 0;
  CHECK(gap8::Dma::Check(c) == "DMA transfer of 0 bytes");
  c = ok;
  c.loc = GAP8_L1_BASE + GAP8_L1_SIZE - 8;
  CHECK(gap8::Dma::Check(c).find("outside L1") != std::string::npos);
  c = ok;
  c.ext = GAP8_L2_BASE + GAP8_L2_SIZE - 8;
  CHECK(gap8::Dma::Check(c).find("outside L2") != std::string::npos);
  c = ok;  // 2-D: 4 rows of 64 bytes, rows 192 KiB apart: the last row ends past L2
  c.length = 64;
  c.stride = 0x30000;
  CHECK(gap8::Dma::Check(c).find("outside L2") != std::string::npos);
  c.stride = 32;
  CHECK(gap8::Dma::Check(c) == "DMA 2-D stride smaller than the row length");
}

TEST_CASE("DMA transfers complete in order after setup + bytes / 8 cycles, then copy") {
  gap8::Memory memory;
  gap8::Dma dma;
  uint8_t src[64];
  for (int i = 0; i < 64; ++i) src[i] = static_cast<uint8_t>(i + 1);
  memory.Write(GAP8_L2_BASE, src, 64);
  const uint32_t a = dma.Push({GAP8_L2_BASE, GAP8_L1_BASE, 64, 1, 0, 0}, 100);
  const uint32_t b = dma.Push({GAP8_L2_BASE, GAP8_L1_BASE + 64, 16, 1, 32, 8}, 100);
  CHECK(dma.NextCompletion() == 100 + gap8::timing::kDmaSetup + 64 / 8);
  CHECK_FALSE(dma.Done(a));
  CHECK(dma.CompleteNext(memory) == a);
  CHECK(dma.Done(a));
  CHECK(dma.NextCompletion() == 100 + gap8::timing::kDmaSetup + 8 + gap8::timing::kDmaSetup + 2 +
                                    2 * gap8::timing::kDmaRowSetup);
  CHECK(dma.CompleteNext(memory) == b);
  uint8_t l1[80];
  memory.Read(GAP8_L1_BASE, l1, 80);
  CHECK(l1[63] == 64);
  CHECK(l1[64] == 1);   // row 0 of the 2-D copy: bytes 0..7
  CHECK(l1[72] == 33);  // row 1 starts 32 bytes further in L2
  CHECK(dma.Idle());
}

TEST_CASE("divider cost: clz(divisor) + 3, negative clz(-d) + 2, zero 1 (GVSOC RI5CY)") {
  using gap8::timing::Divide;
  CHECK(Divide(1, true) == 34u);
  CHECK(Divide(0x80000000u, false) == 3u);
  CHECK(Divide(static_cast<uint32_t>(-1), true) == 33u);
  CHECK(Divide(static_cast<uint32_t>(-1), false) == 3u);
  CHECK(Divide(0, true) == 1u);
  CHECK(Divide(256, false) == 26u);
}
