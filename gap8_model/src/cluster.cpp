// Lockstep scheduling of the cluster's cores. The core whose next issue cycle is earliest runs;
// while it is alone in front it runs many instructions in a row (the fast path); cores issuing in
// the same cycle go through the TCDM bank arbiter first.
#include "gap8/cluster.h"

#include <algorithm>
#include <bit>
#include <cstdio>

#include "core_execute_inline.h"
#include "gap8/timing.h"

namespace gap8 {

namespace {}

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
