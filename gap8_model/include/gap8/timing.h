// Every cycle cost the model charges, in one place, each with its source. "GVSOC" below is the
// GAP8 virtual platform shipped in GreenWaves' gap_sdk (github.com/GreenWaves-Technologies/
// gap_sdk, commit a23026507efe, directory gvsoc/); "gap_configs" is gap_sdk's utils/gap_configs,
// whose generators build the GAP8 platform GVSOC simulates (chips/gap8_revc/gap8_revc.json).
// docs/gap8-model.md has the same table with the reasoning.
#pragma once

#include <cstdint>

namespace gap8::timing {

// ---- RI5CY pipeline (GVSOC iss: rv32i.hpp, rv32m.hpp, perf.hpp; RI5CY user manual) ----
inline constexpr uint32_t kAlu = 1;           // ALU, SIMD, p.*, lp.* set-up, csrr: one cycle
inline constexpr uint32_t kLoadStore = 1;     // TCDM load or store without contention
inline constexpr uint32_t kLoadUseStall = 1;  // next instruction reads the loaded register
inline constexpr uint32_t kMulUseStall = 1;   // next instruction reads the mul result
inline constexpr uint32_t kJumpRegStall = 1;  // jalr reads the register written just before
inline constexpr uint32_t kMulh = 5;          // mulh, mulhsu, mulhu
inline constexpr uint32_t kBranchNotTaken = 1;
inline constexpr uint32_t kBranchTaken = 3;
inline constexpr uint32_t kJump = 2;        // jal, jalr
inline constexpr uint32_t kMisaligned = 1;  // extra cycle: the access is split in two

// ---- TCDM (GVSOC memory_impl.cpp: each L1 bank is a memory of width_bits 2, so it serves one
// 32-bit access per cycle and delays the next by the remaining cycles; 16 banks from
// gap_configs cluster_gen.py, nb_pe 8 x banking_factor 2) ----
inline constexpr uint32_t kTcdmRetry = 1;  // a core that loses its bank this cycle retries next

// ---- L2 seen from the cluster (gap_configs soc_gen.py: the SoC interconnect ll_ico maps L2
// with 'latency': 8 on a chip with an FC interconnect, as GAP8; every router includes
// ips/interco/router.json, bandwidth 4 bytes per cycle, and GVSOC's router_impl.cpp then
// applies only the mapping's latency, so cluster_ico's 2 and axi_ico's 9 add nothing) ----
inline constexpr uint32_t kL2Latency = 8;        // cycles a core load or store to L2 waits
inline constexpr uint32_t kL2BytesPerCycle = 4;  // router bandwidth on the path to L2

// ---- Cluster peripherals (event unit and DMA demux: gap_configs cluster_gen.py maps them in
// each core's pe_ico router without latency; the units answer at once) ----
inline constexpr uint32_t kPeriphAccess = 1;

// ---- Event unit (GVSOC gvsoc_gap/models/pulp/event_unit/eu_v3_impl.cpp, GAP8's eu_v3) ----
// A core's wait (p.elw on a barrier or an empty dispatch FIFO) answers with
// EU_WAKEUP_REQ_LATENCY = 6 cycles; when the event is already there it adds
// EU_WAKEUP_LATENCY = 2 and the core never sleeps. GVSOC's core resumes 1 + latency cycles
// after the answer (iss_wrapper.cpp: enqueue_next_instr(1 + wakeup_latency)).
inline constexpr uint32_t kEuWaitLatency = 6;
inline constexpr uint32_t kEuNoSleepLatency = 2;
// First instruction after a wake-up: this many cycles after the waking event. (A wait whose
// event is already there costs its load, kPeriphAccess, plus both latencies.)
inline constexpr uint32_t kWakeUp = 1 + kEuWaitLatency;

// ---- Shared instruction cache (GVSOC models/cache/cache_impl.cpp; geometry gap8_revc.json:
// nb_sets_bits 6, nb_ways_bits 2, line_size_bits 4 = 64 sets x 4 ways x 16 bytes) ----
inline constexpr uint32_t kIcacheSets = 64;
inline constexpr uint32_t kIcacheWays = 4;
inline constexpr uint32_t kIcacheLineBytes = 16;
// One refill: L2 latency + the 16-byte line's duration on the 4-byte-per-cycle router
// (io_req::get_full_latency = latency + duration) + the cache's refill_latency (0: cache.json
// does not set it). One refill at a time: a second miss waits for the first to finish.
inline constexpr uint32_t kIcacheRefill = kL2Latency + kIcacheLineBytes / kL2BytesPerCycle;
// Code in L1 (rare: the linker script puts code in L2): GVSOC refills through cluster_ico's
// L1 mapping, which has no latency; this model charges the line's duration on the router only.
inline constexpr uint32_t kIcacheRefillFromL1 = kIcacheLineBytes / kL2BytesPerCycle;
// The core's prefetch buffer (GVSOC iss prefetcher.hpp, ISS_PREFETCHER_SIZE = 16 bytes) holds
// one aligned line; an instruction needs the 4 bytes from its pc in it.
inline constexpr uint32_t kPrefetchBytes = 16;
inline constexpr uint32_t kOpcodeMaxBytes = 4;

// ---- Cluster DMA, mchan v6 (GVSOC gvsoc_gap/models/pulp/mchan/mchan_v6_impl.cpp; parameters
// gap_configs ips/mchan/mchan_v6.json) ----
// After the command's last word is written: one cycle to move it from the core queue to the
// global queue, one to send its first burst; the local side starts the cycle after.
inline constexpr uint32_t kDmaFirstBurst = 2;
inline constexpr uint32_t kDmaMaxBurst = 256;      // max_burst_length; 2-D bursts stop at a row
inline constexpr uint32_t kDmaLocalPorts = 2;      // ports writing TCDM (ext -> loc): 0 and 1
inline constexpr uint32_t kDmaLocalPortBytes = 4;  // each port moves one aligned word a cycle

// div, divu, rem, remu: RI5CY's serial divider (rtl/riscv_alu.sv of pulp-platform/riscv, read
// in its copy AlSaqr-platform/riscv_nn; openhwgroup/cv32e40p's cv32e40p_alu.sv is the same: the
// counter starts at div_shift = the divisor's leading zeros, or for a negative divisor of a
// signed op the leading zeros of ~divisor minus one, 31 when there is no one to find;
// rtl/riscv_alu_div.sv: load, div_shift + 1 divide cycles, finish = div_shift + 3). The CV32E40P
// manual's table gives the same range, 3..35, 35 for a zero divisor. GVSOC (rv32m.hpp) counts
// clz(-divisor) + 2 for a negative one: one cycle less when -divisor is a power of two (33 for -1,
// 2 for -2^31, under the manual's minimum); the model follows the RTL.
inline uint32_t Divide(uint32_t divisor, bool is_signed) {
  if (divisor == 0) return 32 + 3;
  if (is_signed && static_cast<int32_t>(divisor) < 0) {
    const uint32_t ones = ~divisor;  // leading ones of the divisor = leading zeros of ~divisor
    return ones == 0 ? 31 + 3 : static_cast<uint32_t>(__builtin_clz(ones)) + 2;
  }
  return static_cast<uint32_t>(__builtin_clz(divisor)) + 3;
}

}  // namespace gap8::timing
