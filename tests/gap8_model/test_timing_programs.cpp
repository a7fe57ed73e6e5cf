// Exact cycle counts of programs/timing.c, derived by hand from the timing rules and their
// sources (timing.h; docs/gap8-model.md walks through each one).
#include <catch2/catch.hpp>

#include "program_runner.h"

namespace {

struct Measured {
  uint32_t cycles, active, instr, imiss, tcdm_cont, ld_ext, st_ext, ld_ext_cyc;
};

Measured RunTiming(uint32_t mode, int cores, bool contention = true) {
  RunOptions options = OnCores(cores);
  options.contention = contention;
  options.before_run = [mode](gap8::Cluster& cluster, const gap8::ElfImage& image) {
    cluster.memory().Write(image.symbols.at("timing_mode"), &mode, 4);
  };
  ProgramRun run = RunProgram("timing", options);
  INFO(run.Describe());
  REQUIRE(run.ok());
  uint32_t r[8];
  REQUIRE(run.cluster->memory().Read(run.image.symbols.at("results"), r, sizeof r));
  return {r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]};
}

}  // namespace

// 8 cold lines, 12 cycles each (8 of L2 latency + 16 bytes at 4 per cycle), one at a time;
// 30 instructions per pass, the taken bnez 3, the start store 1.
TEST_CASE("icache: a cold block of 8 lines costs 8 refills of 12 cycles, in IMISS") {
  const Measured m = RunTiming(0, 1);
  CHECK(m.imiss == 8u * 12u);
  CHECK(m.instr == 63u);
  CHECK(m.cycles == 1u + 1u + 1u + (28u + 1u + 3u) + (28u + 1u + 1u) + 96u);
  CHECK(m.active == m.cycles);
}

// Master: 5 stores (t0..t0+5; the entry push at t0+4), jal 2, ret 1 + jump-register stall 1,
// barrier load at t0+11. Workers wake at t0+4 + 7 (eu_v3: 6 cycles of answer + 1), then lw arg,
// andi, bne, add, jr 2, ret 2: at the barrier at t0+19. The last arriver completes it and the
// others resume 7 cycles later, at t0+26: the master's stop store.
TEST_CASE("fork + barrier: pulp-os's sequence with eu_v3's latencies, exact cycles") {
  const Measured alone = RunTiming(1, 1);
  CHECK(alone.instr == 9u);
  CHECK(alone.cycles == 11u + 1u + 6u + 2u);  // the barrier's event is there: 9 cycles
  CHECK(alone.imiss == 0u);
  // The event unit is external (PMSIS, GVSOC): 5 stores, 1 load whose 8 cycles of answer count.
  CHECK(alone.st_ext == 5u);
  CHECK(alone.ld_ext == 1u);
  CHECK(alone.ld_ext_cyc == 6u + 2u);
  for (int cores : {2, 4, 8}) {
    INFO("cores " << cores);
    const Measured m = RunTiming(1, cores);
    CHECK(m.instr == 9u);
    CHECK(m.cycles == 26u);
    CHECK(m.active == 26u - (19u - 12u));  // asleep from t0+12 to the barrier's event
    CHECK(m.imiss == 0u);
    CHECK(m.ld_ext == 1u);
    CHECK(m.ld_ext_cyc == 0u);  // the load slept: GVSOC's router saw no latency
  }
}

// Push at t0+4 (the third command word): done at t0+4 + 2 + 1024 / 8 = t0+134. Before the wait
// 7 instructions (a load-use stall on the status), asleep from t0+13, awake at t0+141, then
// MASK_AND, j, status, stall, and, beqz taken, free: the stop store at t0+151.
TEST_CASE("DMA 1-D of 1024 bytes: the mchan_v6 schedule plus PMSIS's wait loop, exact cycles") {
  const Measured m = RunTiming(2, 1);
  CHECK(m.instr == 18u);
  CHECK(m.cycles == 151u);
  CHECK(m.active == 151u - (134u - 13u));
  CHECK(m.imiss == 0u);
  CHECK(m.ld_ext == 4u);  // counter, status, event wait, status
  CHECK(m.st_ext == 3u + 1u + 1u + 1u);
}

// The DMA's TCDM pieces take their banks: the load issued at t0+7 meets the DMA's first piece
// in its bank, loses, and retries the next cycle (the DMA keeps its schedule).
TEST_CASE("DMA pieces take TCDM bank cycles: a core's load on that bank waits one cycle") {
  const Measured on = RunTiming(3, 1);
  CHECK(on.instr == 1u + 3u + 8u + 1u);
  CHECK(on.tcdm_cont == 1u);
  CHECK(on.cycles == 1u + 1u + 3u + 8u + 1u);
  const Measured off = RunTiming(3, 1, false);
  CHECK(off.tcdm_cont == 0u);
  CHECK(off.cycles == on.cycles - 1u);
}
