// The cluster's shared cycles: two or more cores issuing in one cycle, the TCDM bank arbiter.
// Apart from cluster.cpp so that GCC's inlining there (RunSolo, the one-core loop) does not
// depend on this code: in one file, RunShared's two instances cost 0.1 % more host
// instructions on one core (callgrind, gap8-run --cores 1 --bench bench.elf).
#include <algorithm>
#include <bit>

#include "core_execute_inline.h"
#include "gap8/cluster.h"
#include "gap8/timing.h"

namespace gap8 {

namespace {

// The awake cores by their next issue cycle, relative to the current one, in a register: byte k
// of `near` holds the cores issuing at cycle + 1 + k (k < 8: a bit per core); the cores further
// ahead are `far`, read from the cores themselves when the earliest of them (far_min) is due.
// Finding the next cycle and its cores is then a bit scan (the scan of eight 64-bit times it
// replaces was 7 % of the host instructions on 8 cores).
class IssueCalendar {
 public:
  // Every awake core not in `ready` issues after `cycle`.
  void Rebuild(const std::vector<Core>& cores, uint32_t ready, uint64_t cycle) {
    near_ = 0;
    far_ = 0;
    far_min_ = ~0ull;
    for (size_t i = 0; i < cores.size(); ++i) {
      if (!((ready >> i) & 1u)) Add(cores[i], static_cast<int>(i), cycle);
    }
  }
  // Core id issued at `cycle`; its next issue cycle is its time (none while asleep).
  void Add(const Core& c, int id, uint64_t cycle) {
    if (!c.asleep) AddAwake(c, id, cycle);
  }
  // The same for a core that cannot be asleep (its issue was no peripheral access).
  void AddAwake(const Core& c, int id, uint64_t cycle) {
    const uint64_t ahead = c.time - cycle - 1;  // a core issuing advances at least one cycle
    if (ahead < 8) [[likely]] {
      near_ |= uint64_t{1} << (8 * ahead + id);
    } else {
      far_ |= 1u << id;
      far_min_ = std::min(far_min_, c.time);
    }
  }
  // The cores of `losers` lost their bank at `cycle`: they retry kTcdmRetry cycles later.
  void AddRetries(uint32_t losers) {
    static_assert(timing::kTcdmRetry >= 1 && timing::kTcdmRetry <= 8);
    near_ |= uint64_t{losers} << (8 * (timing::kTcdmRetry - 1));
  }
  // Moves *cycle to the next cycle a core issues at and returns those cores (0: all asleep).
  uint32_t Next(const std::vector<Core>& cores, uint64_t* cycle) {
    const int k = std::countr_zero(near_) >> 3;  // 8 when near_ is empty
    if (far_ != 0 && far_min_ <= *cycle + 1 + k) [[unlikely]]
      return NextFromCores(cores, cycle);
    if (near_ == 0) return 0;
    *cycle += 1 + k;
    const uint64_t from_k = near_ >> (8 * k);
    near_ = from_k >> 8;
    return static_cast<uint32_t>(from_k & 0xFFu);
  }

 private:
  uint32_t NextFromCores(const std::vector<Core>& cores, uint64_t* cycle) {
    uint64_t next = ~0ull;
    for (const Core& c : cores) next = c.asleep ? next : std::min(next, c.time);
    uint32_t ready = 0;
    for (size_t i = 0; i < cores.size(); ++i)
      ready |= static_cast<uint32_t>(!cores[i].asleep && cores[i].time == next) << i;
    *cycle = next;
    Rebuild(cores, ready, next);
    return ready;
  }

  uint64_t near_ = 0;
  uint32_t far_ = 0;
  uint64_t far_min_ = ~0ull;
};

}  // namespace

// Shared cycles, one after the other while the earliest cycle has two or more cores: the cores
// in `ready` (all issuing at `cycle`) issue, in id order: hazards first, then the TCDM bank
// arbiter, then execution. Within the loop only the issuing cores' next issue cycles change, so
// the loop keeps them in a calendar and finds the next cycle there. It stops where Advance must
// decide: one core alone, a DMA completion, the cycle budget, a wake-up or DMA push, the exit.
// The bank bookkeeping has few data-dependent branches: with eight cores interleaved the host's
// branch predictor guesses poorly.
template <bool kTrace>
void Cluster::RunShared(uint32_t ready, uint64_t cycle) {
  IssueCalendar calendar;
  calendar.Rebuild(cores_, ready, cycle);
  IssueState state;
  for (int i = 0; i < num_cores(); ++i) state.NextSlot(cores_[i], i);
  schedule_changed_ = false;  // a wake-up or a DMA push sets it
  for (;;) {
    IssueCycle<kTrace>(ready, cycle, state, calendar);
    if (exited_ || schedule_changed_) return;
    uint64_t next = cycle;
    const uint32_t next_ready = calendar.Next(cores_, &next);
    if ((next_ready & (next_ready - 1)) == 0 || next > config_.max_cycles) return;
    if (!dma_.Idle() && dma_.NextCompletion() <= next) return;
    cycle = next;
    ready = next_ready;
  }
}

// Always inline: with two instances (kTrace) GCC keeps it out of line, 4 % more host
// instructions on 8 cores (callgrind, gap8-run --cores 8 --bench bench_parallel.elf: 4,914 M).
// A core that lost its bank retries the same instruction (its registers cannot change
// meanwhile): its slot is still its pc's, so the retry needs no fetch; a retried TCDM load that
// cannot stop the run needs only its request (below: 6 % fewer host instructions, 8 % less time
// on 8 cores, docs/measurements/gap8-model-host-speed.md).
// An instruction that touches only its core's own state (OwnStateOnly) and waits for no fetch
// executes in the first pass, without the second one: its place in the cycle's order does not
// matter while no core before it in the order may end the run or rewrite code
// (CannotStopOrRewrite; such a core executes in the second pass, and every core after it too,
// as then the order matters) and no core faults on its fetch (the first pass would throw before
// any execution). Not with a trace, whose lines follow the order.
template <bool kTrace, typename Calendar>
[[gnu::always_inline]] inline void Cluster::IssueCycle(uint32_t ready, uint64_t cycle,
                                                       IssueState& state, Calendar& calendar) {
  CodeSlots& slots = state.slots;
  BankRequests requests{};  // per bank: bit per requesting core
  uint32_t issuing = 0, banks = 0, shared_banks = 0;
  const bool contention = config_.contention;
  bool in_order = kTrace || state.fetch_fault;  // no more executions in the first pass
  uint32_t quick_retry = 0;  // requesting cores whose retry, if they lose, needs only the request
  const auto request = [&](int id, uint32_t bank_bit) {
    issuing |= 1u << id;
    requests[std::countr_zero(bank_bit | (1u << kNoBank))] |= 1u << id;
    shared_banks |= banks & bank_bit;
    banks |= bank_bit;
  };
  // The losers of the cycle before that retry a TCDM load that cannot stop the run: the same
  // instruction (unless a store rewrote it), address and bank (their registers did not change),
  // no hazard (none stalled them then), nothing for in_order. Only the request is recorded
  // again; its place before the other cores does not matter (requests are a set).
  uint32_t full = ready;
  for (uint32_t r = ready & state.retry; r != 0; r &= r - 1) {
    const int id = std::countr_zero(r);
    if (slots[id]->op == Op::kUndecoded) [[unlikely]]
      continue;
    full &= ~(1u << id);
    quick_retry |= 1u << id;
    request(id, state.bank_bit[id]);
  }
  for (uint32_t m = full; m != 0; m &= m - 1) {
    const int id = std::countr_zero(m);
    Core& c = *core_ptr_[id];
    // Not decoded yet, or its bytes were rewritten since (or pc is outside L1 and L2: throws).
    if (slots[id]->op == Op::kUndecoded) [[unlikely]]
      slots[id] = &c.Fetch();
    const Decoded& d = *slots[id];
    if (const uint32_t stall = c.TakeHazardStall(d)) {
      c.time += stall;
      calendar.AddAwake(c, id, cycle);
      continue;
    }
    if (!in_order && c.OwnStateOnly(d) && InPrefetchBuffer(c)) {
      c.time += c.ExecuteInline(d);
      state.NextSlot(c, id);
      calendar.AddAwake(c, id, cycle);
      continue;
    }
    const uint32_t addr = c.AccessAddress(d);
    const bool cannot_stop = c.CannotStopOrRewrite(d, addr);
    in_order = in_order || !cannot_stop;
    const uint32_t bank_bit = contention ? Core::TcdmBankBit(d, addr) : 0u;
    state.bank_bit[id] = bank_bit;
    quick_retry |= static_cast<uint32_t>(cannot_stop && (d.access & kAccessLoad)) << id;
    request(id, bank_bit);
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
  for (uint32_t l = losers; l != 0; l &= l - 1) LoseBank(*core_ptr_[std::countr_zero(l)]);
  calendar.AddRetries(losers);
  state.retry = losers & quick_retry;
  issuing &= ~losers;
  for (uint32_t m = issuing; m != 0 && !exited_; m &= m - 1) {
    const int id = std::countr_zero(m);
    Core& c = *core_ptr_[id];
    Trace<kTrace>(c, *slots[id]);
    const uint32_t fetch = FetchStall(c);
    c.time += c.ExecuteInline(*slots[id]) + fetch;
    if (fetch != 0) c.event(GAP8_EVT_IMISS) += fetch;
    state.NextSlot(c, id);
    calendar.Add(c, id, cycle);  // a peripheral read may have put it to sleep
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

template void Cluster::RunShared<false>(uint32_t ready, uint64_t cycle);
template void Cluster::RunShared<true>(uint32_t ready, uint64_t cycle);

}  // namespace gap8
