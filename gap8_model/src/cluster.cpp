// Lockstep scheduling of the cluster's cores. The core whose next issue cycle is earliest runs;
// while it is alone in front it runs many instructions in a row (the fast path); cores issuing in
// the same cycle go through the TCDM bank arbiter first.
#include "gap8/cluster.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <limits>

#include "core_execute_inline.h"
#include "gap8/timing.h"

namespace gap8 {

namespace {
constexpr uint64_t kNever = std::numeric_limits<uint64_t>::max();
}

Cluster::Cluster(ClusterConfig config) : config_(std::move(config)) {
  config_.cores = std::clamp(config_.cores, 1, static_cast<int>(GAP8_MAX_CORES));
  if (!config_.putc) config_.putc = [](char c) { std::fputc(c, stdout); };
  cores_.reserve(config_.cores);  // never reallocated: a Core& stays valid across Start
  for (int i = 0; i < config_.cores; ++i) {
    cores_.emplace_back(i, memory_, this);
    core_ptr_[i] = &cores_[i];
  }
  side_.resize(config_.cores);
}

void Cluster::Start(uint32_t entry) {
  const int n = num_cores();
  cores_.clear();
  for (int i = 0; i < n; ++i) {
    cores_.emplace_back(i, memory_, this);
    cores_[i].set_pc(entry);
    core_ptr_[i] = &cores_[i];
    side_[i] = CoreSide{};
  }
  icache_.Reset();
  dma_ = Dma{};
  // As after pulp-os's cluster start-up: every core in the dispatch team and the barrier.
  all_cores_ = (1u << num_cores()) - 1u;
  dispatch_team_ = barrier_mask_ = barrier_target_ = all_cores_;
  barrier_arrived_ = 0;
  dma_allocated_ = 0;
  exited_ = false;
  retry_mask_ = 0;
}

RunResult Cluster::Run() {
  RunResult result;
  try {
    while (!exited_) Advance();
  } catch (const Fault& fault) {
    result.fault = fault;
    for (auto& c : cores_) result.cycles = std::max(result.cycles, c.time);
    return result;
  }
  // Cores asleep at exit slept until the end: their cycle counts reach the exit cycle.
  for (auto& c : cores_) {
    if (c.asleep && c.time < exit_cycle_) {
      c.slept += exit_cycle_ - c.time;
      c.time = exit_cycle_;
    }
  }
  result.exit_code = exit_code_;
  result.cycles = exit_cycle_;
  return result;
}

void Cluster::Advance() {
  // One pass over the cores: the earliest issue cycle, every core issuing then (ready), and the
  // next issue cycle after it (second_time; equal to first_time when two cores share it).
  uint64_t first_time = kNever, second_time = kNever;
  uint32_t ready = 0;  // bit per core
  for (int i = 0; i < num_cores(); ++i) {
    const Core& c = cores_[i];
    if (c.asleep) continue;
    if (c.time < first_time) {
      second_time = first_time;
      first_time = c.time;
      ready = 1u << i;
    } else if (c.time == first_time) {
      second_time = first_time;
      ready |= 1u << i;
    } else if (c.time < second_time) {
      second_time = c.time;
    }
  }
  // A transfer completing at cycle t is visible to instructions issuing at t.
  if (!dma_.Idle() && dma_.NextCompletion() <= first_time) return CompleteDma();
  if (!ready) ReportDeadlock();
  Core& first = cores_[std::countr_zero(ready)];  // the lowest id among the earliest
  if (first_time > config_.max_cycles) {
    const Decoded& d = first.Fetch();
    throw Fault{FaultKind::kCycleBudget, first.id(), first.pc(), d.raw,
                "cycle budget of " + std::to_string(config_.max_cycles) + " cycles exceeded"};
  }
  const bool trace = static_cast<bool>(config_.trace);
  if (second_time == first_time)
    return trace ? RunShared<true>(ready, first_time) : RunShared<false>(ready, first_time);
  uint64_t limit = std::min(second_time, config_.max_cycles + 1);
  if (!dma_.Idle()) limit = std::min(limit, dma_.NextCompletion());
  trace ? RunSolo<true>(first, limit) : RunSolo<false>(first, limit);
}

template <bool kTrace>
void Cluster::RunSolo(Core& core, uint64_t limit) {
  schedule_changed_ = false;  // a DMA push sets it, so dma_end stays right
  retry_mask_ &= ~(1u << core.id());
  const uint64_t dma_end = config_.contention ? dma_.BankTrafficEnd() : 0;
  while (core.time < limit && !core.asleep && !exited_ && !schedule_changed_) {
    const Decoded& d = core.Fetch();
    if (const uint32_t stall = core.TakeHazardStall(d)) {
      core.time += stall;
      continue;
    }
    if (core.time < dma_end && (core.TcdmBankBit(d) & dma_.BanksAt(core.time))) {
      LoseBank(core);
      continue;
    }
    if (const uint32_t fetch = FetchStall(core)) [[unlikely]] {
      Trace<kTrace>(core, d);
      core.time += core.ExecuteInline(d) + fetch;
      core.event(GAP8_EVT_IMISS) += fetch;
      continue;
    }
    Trace<kTrace>(core, d);
    core.time += core.ExecuteInline(d);
  }
}

// Shared cycles, one after the other while the earliest cycle has two or more cores: the cores
// in `ready` (all issuing at `cycle`) issue, in id order: hazards first, then the TCDM bank
// arbiter, then execution. Within the loop only the issuing cores' next issue cycles change, so
// the loop keeps every core's in `t` and finds the next cycle there. It stops where Advance must
// decide: one core alone, a DMA completion, the cycle budget, a wake-up or DMA push, the exit.
// The bank bookkeeping has few data-dependent branches: with eight cores interleaved the host's
// branch predictor guesses poorly.
template <bool kTrace>
void Cluster::RunShared(uint32_t ready, uint64_t cycle) {
  std::array<uint64_t, GAP8_MAX_CORES> t;  // next issue cycle per core, kNever asleep or absent
  t.fill(kNever);
  for (int i = 0; i < num_cores(); ++i) t[i] = cores_[i].asleep ? kNever : cores_[i].time;
  const auto issued = [&](const Core& c, int id) { t[id] = c.asleep ? kNever : c.time; };
  schedule_changed_ = false;  // a wake-up or a DMA push sets it
  for (;;) {
    IssueCycle<kTrace>(ready, cycle, issued);
    if (exited_ || schedule_changed_) return;
    uint64_t next = kNever;  // all GAP8_MAX_CORES entries: the compiler unrolls both loops
    for (uint64_t ti : t) next = std::min(next, ti);
    uint32_t next_ready = 0;
    for (uint32_t i = 0; i < GAP8_MAX_CORES; ++i)
      next_ready |= static_cast<uint32_t>(t[i] == next) << i;
    if ((next_ready & (next_ready - 1)) == 0 || next == kNever || next > config_.max_cycles) return;
    if (!dma_.Idle() && dma_.NextCompletion() <= next) return;
    cycle = next;
    ready = next_ready;
  }
}

// Always inline: with two instances (kTrace) GCC keeps it out of line, 4 % more host
// instructions on 8 cores (callgrind, gap8-run --cores 8 --bench bench_parallel.elf: 4,914 M).
template <bool kTrace, typename Issued>
[[gnu::always_inline]] inline void Cluster::IssueCycle(uint32_t ready, uint64_t cycle,
                                                       const Issued& issued) {
  std::array<const Decoded*, GAP8_MAX_CORES> insn;  // valid for the cores in `issuing`
  std::array<uint32_t, GAP8_MAX_CORES> bank_of;     // likewise: the bank bit each asks for
  BankRequests requests{};                          // per bank: bit per requesting core
  uint32_t issuing = 0, banks = 0, shared_banks = 0;
  const bool contention = config_.contention;
  // Retries kept from a cycle before a code change are void: fetch again.
  if (memory_.code_epoch() != retry_epoch_) retry_mask_ = 0;
  for (uint32_t m = ready; m != 0; m &= m - 1) {
    const int id = std::countr_zero(m);
    Core& c = *core_ptr_[id];
    uint32_t bank_bit;
    if ((retry_mask_ >> id) & 1u) {
      insn[id] = retry_insn_[id];
      bank_bit = retry_bank_[id];
    } else {
      const Decoded& d = c.Fetch();
      if (const uint32_t stall = c.TakeHazardStall(d)) {
        c.time += stall;
        issued(c, id);
        continue;
      }
      insn[id] = &d;
      bank_bit = contention ? c.TcdmBankBit(d) : 0u;
    }
    bank_of[id] = bank_bit;
    issuing |= 1u << id;
    requests[std::countr_zero(bank_bit | (1u << kNoBank))] |= 1u << id;
    shared_banks |= banks & bank_bit;
    banks |= bank_bit;
  }
  uint32_t losers = 0;  // each retries next cycle
  // Banks the DMA takes this cycle: every core requesting one retries (the DMA always wins).
  if (const uint32_t dma_banks = contention ? dma_.BanksAt(cycle) & banks : 0) {
    for (uint32_t b = dma_banks; b != 0; b &= b - 1) losers |= requests[std::countr_zero(b)];
    banks &= ~dma_banks;
    shared_banks &= ~dma_banks;
  }
  // A bank with one requester: it wins, and the round-robin pointer moves past it.
  for (uint32_t b = banks & ~shared_banks; b != 0; b &= b - 1) {
    const int bank = std::countr_zero(b);
    bank_priority_[bank] = NextCore(std::countr_zero(requests[bank]));
  }
  if (shared_banks != 0) losers |= ArbitrateSharedBanks(shared_banks, requests);
  retry_mask_ = (retry_mask_ & ~ready) | losers;
  retry_epoch_ = memory_.code_epoch();
  for (uint32_t l = losers; l != 0; l &= l - 1) {
    const int id = std::countr_zero(l);
    LoseBank(*core_ptr_[id]);
    retry_insn_[id] = insn[id];
    retry_bank_[id] = bank_of[id];
    issued(*core_ptr_[id], id);
  }
  issuing &= ~losers;
  for (uint32_t m = issuing; m != 0 && !exited_; m &= m - 1) {
    const int id = std::countr_zero(m);
    Core& c = *core_ptr_[id];
    Trace<kTrace>(c, *insn[id]);
    const uint32_t fetch = FetchStall(c);
    c.time += c.ExecuteInline(*insn[id]) + fetch;
    c.event(GAP8_EVT_IMISS) += fetch;
    issued(c, id);
  }
}

// Banks requested by two or more cores: round robin, the first requester at or after the bank's
// priority pointer wins; each loser stalls one cycle and retries. Returns the losers.
uint32_t Cluster::ArbitrateSharedBanks(uint32_t shared_banks, const BankRequests& requests) {
  uint32_t all_losers = 0;
  for (; shared_banks != 0; shared_banks &= shared_banks - 1) {
    const int b = std::countr_zero(shared_banks);
    const uint32_t mask = requests[b];
    const uint32_t from_pointer = mask & ~((1u << bank_priority_[b]) - 1u);
    const int winner = std::countr_zero(from_pointer ? from_pointer : mask);
    bank_priority_[b] = NextCore(winner);
    all_losers |= mask & ~(1u << winner);
  }
  return all_losers;
}

// The transfer's event goes to every core (broadcast, as PMSIS asks) or to the one that queued
// it (mchan_v6 Mchan_channel::trigger_event); a core waiting for it wakes (eu_v3 check_state).
void Cluster::CompleteDma() {
  const uint64_t at = dma_.NextCompletion();
  const Dma::Completion done = dma_.CompleteNext(memory_);
  if (!done.event) return;
  for (auto& c : cores_) {
    if (!done.broadcast && static_cast<uint32_t>(c.id()) != done.core) continue;
    CoreSide& s = side_[c.id()];
    s.evt_status |= 1u << GAP8_EVT_DMA;
    if (c.asleep && s.wait == Wait::kEvent && (s.evt_status & s.evt_mask)) {
      s.evt_status &= ~s.evt_mask;
      WakeCore(c, at, 0);
    }
  }
}

void Cluster::SleepOn(Core& core, Wait reason) {
  CoreSide& s = side_[core.id()];
  s.wait = reason;
  s.wait_pc = core.pc();
  s.wait_insn = core.current() ? core.current()->raw : 0;
  core.Sleep();
}

void Cluster::WakeCore(Core& core, uint64_t at, uint32_t value) {
  side_[core.id()].wait = Wait::kNone;
  core.Wake(at, value);
  schedule_changed_ = true;
}

}  // namespace gap8

namespace gap8 {

// Every core sleeps and no DMA transfer is pending: nothing can ever wake them. Name the core
// most likely at fault: one in a barrier, else one waiting for DMA, else the lowest asleep.
void Cluster::ReportDeadlock() {
  int chosen = -1;
  for (Wait w : {Wait::kBarrier, Wait::kEvent, Wait::kDispatch}) {
    for (int i = 0; i < num_cores() && chosen < 0; ++i) {
      if (side_[i].wait == w) chosen = i;
    }
    if (chosen >= 0) break;
  }
  if (chosen < 0) chosen = 0;
  const CoreSide& s = side_[chosen];
  std::string what;
  switch (s.wait) {
    case Wait::kBarrier:
      what = "barrier never completes: " + std::to_string(std::popcount(barrier_arrived_)) +
             " of " + std::to_string(std::popcount(barrier_mask_)) + " team cores arrived";
      break;
    case Wait::kEvent:
      what = "waits for an event (mask " + Hex(s.evt_mask) + ") that nothing will raise";
      break;
    default:
      what = "every core is asleep waiting for a dispatch";
      break;
  }
  throw Fault{FaultKind::kDeadlock, chosen, s.wait_pc, s.wait_insn, what};
}

}  // namespace gap8
