// The GAP8 cluster: N cores in lockstep over shared L1/L2, the event unit (fork, barrier), the
// DMA and the per-core counters. Time is discrete: the core with the earliest next-issue cycle
// runs next; cores issuing in the same cycle are arbitrated per TCDM bank.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "gap8/core.h"
#include "gap8/dma.h"
#include "gap8/fault.h"
#include "gap8/icache.h"
#include "gap8/memory.h"

namespace gap8 {

struct ClusterConfig {
  int cores = 8;                           // 1..8
  bool contention = true;                  // model TCDM bank conflicts
  uint64_t max_cycles = 4'000'000'000ull;  // a runaway program faults past this
  std::function<void(char)> putc;          // program output; stdout when empty
  // Called before each instruction executes (gap8-run --trace): its core, issue cycle, pc and
  // bits. Empty: no tracing, and the issue loops run without the test.
  std::function<void(int core, uint64_t cycle, uint32_t pc, uint32_t bits)> trace;
};

struct RunResult {
  std::optional<Fault> fault;  // set when the run ended on a fault
  int exit_code = 0;           // the program's exit status when it exited
  uint64_t cycles = 0;         // cluster cycles until exit (or the fault)
};

class Cluster {
 public:
  explicit Cluster(ClusterConfig config);
  // The cores point back at their cluster, and it at them: not copyable or movable.
  Cluster(const Cluster&) = delete;
  Cluster& operator=(const Cluster&) = delete;

  Memory& memory() { return memory_; }
  const ICache& icache() const { return icache_; }
  Core& core(int i) { return cores_[i]; }
  int num_cores() const { return config_.cores; }  // cores_.size(), without a division

  // Every core starts at `entry` at cycle 0 (start-up code splits them by core id).
  void Start(uint32_t entry);
  RunResult Run();

  // Peripheral port, used by the cores' loads and stores (32-bit aligned words only).
  bool IsPeripheral(uint32_t addr, uint32_t bytes) const;
  // The event unit and the DMA: reached through the cores' pe_ico routers like L2, so counted
  // in LD_EXT / ST_EXT (PMSIS: "every non-TCDM access is considered external"; GVSOC's
  // cluster_gen.py gives their mappings id 1, the external counters' id). The control and
  // counter registers stand for things GAP8 reaches otherwise (CSRs, the host) and are not.
  static bool IsExternalPeripheral(uint32_t addr) {
    return addr - GAP8_EU_BASE < 0x100u || addr - GAP8_DMA_QUEUE < 0x100u;
  }
  // A read's cycles beyond the access itself (an event-unit wait) go to *extra.
  uint32_t PeripheralRead(Core& core, uint32_t addr, uint32_t* extra);
  void PeripheralWrite(Core& core, uint32_t addr, uint32_t value);

 private:
  enum class Wait : uint8_t { kNone, kDispatch, kBarrier, kEvent };
  static constexpr uint64_t kNever = ~0ull;  // the next issue cycle of a core asleep or absent
  struct CoreSide {                          // event-unit and DMA state private to one core
    Wait wait = Wait::kNone;
    uint32_t wait_pc = 0, wait_insn = 0;
    std::deque<uint32_t> dispatch;  // values pushed to this core, not yet popped
    uint32_t evt_mask = 0, evt_status = 0;
    std::array<uint32_t, 4> dma_words{};  // the DMA command being written
    uint32_t dma_step = 0;
    uint32_t dma_counter = 0;  // counter this core allocated last (its channel's current one)
  };

  void Advance();
  // kTrace: config_.trace is set (Advance picks the instance once, not per instruction).
  template <bool kTrace>
  void RunSolo(Core& core, uint64_t limit);
  // Per TCDM bank, bit per core requesting it; the spare slot kNoBank collects the cores making
  // no TCDM access (so recording a request needs no branch) and is never read.
  static constexpr int kNoBank = GAP8_L1_BANKS;
  using BankRequests = std::array<uint32_t, GAP8_L1_BANKS + 1>;

  template <bool kTrace>
  void RunShared(uint32_t ready, uint64_t cycle);
  // One shared cycle; the calendar gets the next issue cycle of each core of `ready` whose next
  // issue cycle is known (all but those after an exit).
  using CodeSlots = std::array<const Decoded*, GAP8_MAX_CORES>;
  struct IssueState {
    CodeSlots slots{};         // per core: the decode-cache slot of its pc (Core::CodeSlot)
    bool fetch_fault = false;  // a core's pc is outside L1 and L2: its next issue faults
    uint32_t retry = 0;        // cores retrying a TCDM load next cycle with the bank bit below
    std::array<uint32_t, GAP8_MAX_CORES> bank_bit{};  // per core: its last request's bank bit
    void NextSlot(const Core& c, int id) {
      if (Memory::InL2(c.pc())) [[likely]] {
        slots[id] = c.CodeSlot();  // the same test inside: GCC merges them
        return;
      }
      slots[id] = c.CodeSlot();
      fetch_fault |= Core::IsNoSlot(slots[id]);
    }
  };
  template <bool kTrace, typename Calendar>
  void IssueCycle(uint32_t ready, uint64_t cycle, IssueState& state, Calendar& calendar);
  template <bool kTrace>
  void Trace(const Core& core, const Decoded& d) const {
    if constexpr (kTrace) config_.trace(core.id(), core.time, core.pc(), d.raw);
  }
  // Cycles the core waits for the instruction at its pc: 0 while the prefetch buffer holds it
  // (the fast path), else the instruction-cache accesses of FetchLines. Counted in IMISS after
  // the instruction executed (it may read the counters itself).
  uint32_t FetchStall(Core& core) { return InPrefetchBuffer(core) ? 0 : FetchLines(core); }
  static bool InPrefetchBuffer(const Core& core) {
    return core.pc() - core.prefetch_base <= timing::kPrefetchBytes - timing::kOpcodeMaxBytes;
  }
  uint32_t FetchLines(Core& core);  // below the class: inline, the host's hot path
  uint32_t ArbitrateSharedBanks(uint32_t shared_banks, const BankRequests& requests);
  // Round robin: the core after `id` (the pointer a bank's winner leaves behind).
  int NextCore(int id) const { return id + 1 == num_cores() ? 0 : id + 1; }
  void CompleteDma();
  // The core lost its TCDM bank this cycle (to another core or to the DMA): it retries next.
  // GVSOC's TCDM bank serves one access a cycle, first come first served; this model lets the
  // DMA's pieces come first, so its schedule (dma.cpp) never moves.
  static void LoseBank(Core& core) {
    core.time += timing::kTcdmRetry;
    core.event(GAP8_EVT_TCDM_CONT) += timing::kTcdmRetry;
  }
  [[noreturn]] void ReportDeadlock();
  void SleepOn(Core& core, Wait reason);
  void WakeCore(Core& core, uint64_t at, uint32_t value);
  uint32_t EventUnitRead(Core& core, uint32_t addr, uint32_t* extra);
  uint32_t BarrierWait(Core& core, uint32_t* extra);
  void EventUnitWrite(Core& core, uint32_t addr, uint32_t value);
  uint32_t DmaRead(Core& core, uint32_t addr);
  void DmaWrite(Core& core, uint32_t addr, uint32_t value);
  void DmaCommandWord(Core& core, uint32_t value);
  void PerfWrite(Core& core, uint32_t addr, uint32_t value);
  [[noreturn]] void BadRegister(Core& core, uint32_t addr);

  ClusterConfig config_;
  Memory memory_;
  std::vector<Core> cores_;  // contiguous: the scheduler reads every core's time each cycle
  // &cores_[i], one load in the issue loops: indexing cores_ there instead costs 3.5 % more host
  // instructions (callgrind, gap8-run --cores 8 --bench bench_parallel.elf: 4,888 M, not 4,722 M).
  std::array<Core*, GAP8_MAX_CORES> core_ptr_{};
  std::vector<CoreSide> side_;
  Dma dma_;
  ICache icache_;
  uint32_t all_cores_ = 1;       // bit per core of the cluster
  uint32_t dispatch_team_ = 1;   // cores receiving dispatch pushes
  uint32_t barrier_mask_ = 1;    // cores that must arrive at the barrier
  uint32_t barrier_target_ = 1;  // cores woken when it completes
  uint32_t barrier_arrived_ = 0;
  uint32_t dma_allocated_ = 0;                      // bit per DMA counter
  std::array<int, GAP8_L1_BANKS> bank_priority_{};  // round-robin: core served first next time
  bool schedule_changed_ = false;  // a wake-up or DMA push: RunSolo and RunShared must yield
  bool exited_ = false;
  int exit_code_ = 0;
  uint64_t exit_cycle_ = 0;
};

// GVSOC's prefetcher (iss prefetcher.hpp): the buffer holds one aligned 16-byte line and the
// instruction needs the 4 bytes from its pc; outside the buffer it refills with pc's line, and
// an instruction at a line's last half-word also needs the next line. As in GVSOC
// (ISS_EXEC_NO_FETCH_COMMON), the wait is added to the instruction's own cycles (and to IMISS,
// which GVSOC means to count but zeroes first: exec.hpp resets fetch_cycles before adding it).
inline uint32_t Cluster::FetchLines(Core& core) {
  const uint32_t pc = core.pc();
  uint32_t stall = 0;
  auto fetch = [&](uint32_t line) {
    const bool in_l2 = line - GAP8_L2_BASE < GAP8_L2_SIZE;
    stall += icache_.Access(line, core.time + stall,
                            in_l2 ? timing::kIcacheRefill : timing::kIcacheRefillFromL1);
    core.prefetch_base = line;
  };
  if (pc - core.prefetch_base >= timing::kPrefetchBytes) fetch(pc & ~(timing::kPrefetchBytes - 1));
  if (pc - core.prefetch_base > timing::kPrefetchBytes - timing::kOpcodeMaxBytes)
    fetch(core.prefetch_base + timing::kPrefetchBytes);
  return stall;
}

}  // namespace gap8
