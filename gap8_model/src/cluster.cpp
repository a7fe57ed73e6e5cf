// Lockstep scheduling of the cluster's cores. The core whose next issue cycle is earliest runs;
// while it is alone in front it runs many instructions in a row (the fast path); cores issuing in
// the same cycle go through the TCDM bank arbiter first.
#include "gap8/cluster.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <limits>

#include "gap8/timing.h"

namespace gap8 {

namespace {
constexpr uint64_t kNever = std::numeric_limits<uint64_t>::max();
}

Cluster::Cluster(ClusterConfig config) : config_(std::move(config)) {
  config_.cores = std::clamp(config_.cores, 1, static_cast<int>(GAP8_MAX_CORES));
  if (!config_.putc) config_.putc = [](char c) { std::fputc(c, stdout); };
  for (int i = 0; i < config_.cores; ++i)
    cores_.push_back(std::make_unique<Core>(i, memory_, this));
  side_.resize(config_.cores);
}

void Cluster::Start(uint32_t entry) {
  for (int i = 0; i < num_cores(); ++i) {
    cores_[i] = std::make_unique<Core>(i, memory_, this);
    cores_[i]->set_pc(entry);
    side_[i] = CoreSide{};
  }
  team_size_ = static_cast<uint32_t>(num_cores());
  barrier_arrived_ = 0;
  exited_ = false;
}

RunResult Cluster::Run() {
  RunResult result;
  try {
    while (!exited_) Advance();
  } catch (const Fault& fault) {
    result.fault = fault;
    for (auto& c : cores_) result.cycles = std::max(result.cycles, c->time);
    return result;
  }
  // Cores asleep at exit slept until the end: their cycle counts reach the exit cycle.
  for (auto& c : cores_) {
    if (c->asleep && c->time < exit_cycle_) {
      c->slept += exit_cycle_ - c->time;
      c->time = exit_cycle_;
    }
  }
  result.exit_code = exit_code_;
  result.cycles = exit_cycle_;
  return result;
}

void Cluster::Advance() {
  uint64_t first_time = kNever, second_time = kNever;
  Core* first = nullptr;
  for (auto& c : cores_) {
    if (c->asleep) continue;
    if (c->time < first_time) {
      second_time = first_time;
      first_time = c->time;
      first = c.get();
    } else if (c->time < second_time) {
      second_time = c->time;
    }
  }
  // A transfer completing at cycle t is visible to instructions issuing at t.
  if (!dma_.Idle() && dma_.NextCompletion() <= first_time) return CompleteDma();
  if (!first) ReportDeadlock();
  if (first_time > config_.max_cycles) {
    const Decoded& d = first->Fetch();
    throw Fault{FaultKind::kCycleBudget, first->id(), first->pc(), d.raw,
                "cycle budget of " + std::to_string(config_.max_cycles) + " cycles exceeded"};
  }
  if (second_time == first_time) return IssueCycle(first_time);
  uint64_t limit = std::min(second_time, config_.max_cycles + 1);
  if (!dma_.Idle()) limit = std::min(limit, dma_.NextCompletion());
  RunSolo(*first, limit);
}

void Cluster::RunSolo(Core& core, uint64_t limit) {
  schedule_changed_ = false;
  while (core.time < limit && !core.asleep && !exited_ && !schedule_changed_) {
    const Decoded& d = core.Fetch();
    if (core.TakeHazardStall(d)) {
      core.time += 1;
      continue;
    }
    core.time += core.Execute(d);
  }
}

void Cluster::IssueCycle(uint64_t cycle) {
  std::array<const Decoded*, GAP8_MAX_CORES> insn{};
  std::array<uint32_t, GAP8_L1_BANKS> requests{};  // per bank: bit per requesting core
  uint32_t banks = 0;                              // bit per bank with a request
  for (auto& c : cores_) {
    if (c->asleep || c->time != cycle) continue;
    const Decoded& d = c->Fetch();
    if (c->TakeHazardStall(d)) {
      c->time += 1;
      continue;
    }
    insn[c->id()] = &d;
    const int bank = config_.contention ? c->TcdmBank(d) : -1;
    if (bank >= 0) {
      requests[bank] |= 1u << c->id();
      banks |= 1u << bank;
    }
  }
  for (; banks != 0; banks &= banks - 1) {
    const int b = std::countr_zero(banks);
    // Round robin: the first requester at or after the bank's priority pointer wins.
    const uint32_t mask = requests[b];
    const uint32_t from_pointer = mask & ~((1u << bank_priority_[b]) - 1u);
    const int winner = std::countr_zero(from_pointer ? from_pointer : mask);
    bank_priority_[b] = (winner + 1) % num_cores();
    for (uint32_t losers = mask & ~(1u << winner); losers != 0; losers &= losers - 1) {
      Core& loser = *cores_[std::countr_zero(losers)];
      insn[loser.id()] = nullptr;  // retries next cycle
      loser.time += 1;
      ++loser.event(GAP8_EVT_TCDM_CONT);
    }
  }
  for (int id = 0; id < num_cores() && !exited_; ++id) {
    if (insn[id]) cores_[id]->time += cores_[id]->Execute(*insn[id]);
  }
}

void Cluster::CompleteDma() {
  const uint64_t at = dma_.NextCompletion();
  const uint32_t id = dma_.CompleteNext(memory_);
  for (auto& c : cores_) {
    CoreSide& s = side_[c->id()];
    if (c->asleep && s.wait == Wait::kDma && s.wait_dma_id <= id) WakeCore(*c, at, 0);
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
  for (Wait w : {Wait::kBarrier, Wait::kDma, Wait::kDispatch}) {
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
             " of " + std::to_string(team_size_) + " team cores arrived";
      break;
    case Wait::kDma:
      what = "waits for DMA transfer " + std::to_string(s.wait_dma_id) + " that was never queued";
      break;
    default:
      what = "every core is asleep waiting for a dispatch";
      break;
  }
  throw Fault{FaultKind::kDeadlock, chosen, s.wait_pc, s.wait_insn, what};
}

}  // namespace gap8
