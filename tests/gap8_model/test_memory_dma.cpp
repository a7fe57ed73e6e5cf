// DMA command checks (the DMA's timing: test_timing.cpp).
#include <catch2/catch.hpp>

#include "gap8/dma.h"

TEST_CASE("DMA commands outside L1 or L2 are refused with a reason") {
  gap8::DmaCommand ok{GAP8_L2_BASE, GAP8_L1_BASE, 256, 1, 0, 0};
  CHECK(gap8::Dma::Check(ok).empty());
  gap8::DmaCommand c = ok;
  c.size = 0;
  CHECK(gap8::Dma::Check(c) == "DMA transfer of 0 bytes (mchan sizes are 1..65535)");
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
