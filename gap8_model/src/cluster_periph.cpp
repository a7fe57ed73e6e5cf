// The cluster's memory-mapped peripherals: control, event unit, DMA and performance counters.
// Register addresses are in runtime/gap8_regs.h; costs in include/gap8/timing.h.
#include <bit>

#include "gap8/cluster.h"
#include "gap8/timing.h"

namespace gap8 {

bool Cluster::IsPeripheral(uint32_t addr, uint32_t bytes) const {
  return addr - GAP8_PERIPH_BASE < GAP8_PERIPH_SIZE && bytes == 4 && (addr & 3u) == 0;
}

void Cluster::BadRegister(Core& core, uint32_t addr) {
  core.Raise(FaultKind::kMemory, "access to unmapped peripheral register " + Hex(addr));
}

uint32_t Cluster::PeripheralRead(Core& core, uint32_t addr) {
  if (addr >= GAP8_PERF_VALUE(0) && addr < GAP8_PERF_VALUE(GAP8_EVT_COUNT)) {
    const int event = static_cast<int>((addr - GAP8_PERF_VALUE(0)) / 4);
    return static_cast<uint32_t>(core.perf().Read(event, core.Totals()));
  }
  switch (addr) {
    case GAP8_CTRL_NUM_CORES:
      return static_cast<uint32_t>(num_cores());
    case GAP8_CTRL_CORE_ID:
      return static_cast<uint32_t>(core.id());
    case GAP8_EU_TEAM_SIZE:
      return team_size_;
    case GAP8_EU_WAIT_ENTRY:
    case GAP8_EU_WAIT_ARG:
    case GAP8_EU_BARRIER:
      return EventUnitRead(core, addr);
    case GAP8_DMA_PUSH:
      return DmaRead(core, addr);
    default:
      BadRegister(core, addr);
  }
}

void Cluster::PeripheralWrite(Core& core, uint32_t addr, uint32_t value) {
  switch (addr) {
    case GAP8_CTRL_EXIT:
      exited_ = true;
      exit_code_ = static_cast<int32_t>(value);
      exit_cycle_ = core.time + timing::kPeriphAccess;
      return;
    case GAP8_CTRL_PUTC:
      config_.putc(static_cast<char>(value & 0xFFu));
      return;
    case GAP8_EU_TEAM_SIZE:
    case GAP8_EU_FORK_ARG:
    case GAP8_EU_FORK_ENTRY:
      return EventUnitWrite(core, addr, value);
    case GAP8_DMA_EXT:
    case GAP8_DMA_LOC:
    case GAP8_DMA_SIZE:
    case GAP8_DMA_DIR:
    case GAP8_DMA_STRIDE:
    case GAP8_DMA_LENGTH:
    case GAP8_DMA_WAIT:
      return DmaWrite(core, addr, value);
    case GAP8_PERF_CONF:
    case GAP8_PERF_RESET:
    case GAP8_PERF_START:
    case GAP8_PERF_STOP:
      return PerfWrite(core, addr, value);
    default:
      BadRegister(core, addr);
  }
}

void Cluster::PerfWrite(Core& core, uint32_t addr, uint32_t value) {
  const EventTotals now = core.Totals();
  if (addr == GAP8_PERF_CONF) core.perf().Configure(value);
  if (addr == GAP8_PERF_RESET) core.perf().Reset(now);
  if (addr == GAP8_PERF_START) core.perf().Start(now);
  if (addr == GAP8_PERF_STOP) core.perf().Stop(now);
}

uint32_t Cluster::EventUnitRead(Core& core, uint32_t addr) {
  CoreSide& s = side_[core.id()];
  if (addr == GAP8_EU_WAIT_ARG) return s.arg;
  if (addr == GAP8_EU_WAIT_ENTRY) {
    if (s.mailbox.empty()) {
      SleepOn(core, Wait::kDispatch);
      return 0;
    }
    const Dispatch d = s.mailbox.front();
    s.mailbox.pop_front();
    s.arg = d.arg;
    return d.entry;
  }
  // Barrier: the last core of the team to arrive releases the others and goes on.
  const uint32_t bit = 1u << core.id();
  if (static_cast<uint32_t>(core.id()) >= team_size_) {
    core.Raise(FaultKind::kDeadlock,
               "barrier on a core outside the team of " + std::to_string(team_size_));
  }
  barrier_arrived_ |= bit;
  if (static_cast<uint32_t>(std::popcount(barrier_arrived_)) < team_size_) {
    SleepOn(core, Wait::kBarrier);
    return 0;
  }
  const uint64_t at = core.time + timing::kPeriphAccess;
  for (auto& c : cores_) {
    if (c.get() != &core && (barrier_arrived_ >> c->id()) & 1u) WakeCore(*c, at, 0);
  }
  barrier_arrived_ = 0;
  return 0;
}

void Cluster::EventUnitWrite(Core& core, uint32_t addr, uint32_t value) {
  if (addr == GAP8_EU_TEAM_SIZE) {
    // 0 means every core, as PMSIS's nb_cores = 0; larger than the cluster is clamped.
    const uint32_t n = static_cast<uint32_t>(num_cores());
    team_size_ = (value == 0 || value > n) ? n : value;
    return;
  }
  if (addr == GAP8_EU_FORK_ARG) {
    fork_arg_ = value;
    return;
  }
  // Fork: dispatch (entry, arg) to every other core of the team.
  const uint64_t at = core.time + timing::kPeriphAccess;
  for (uint32_t i = 0; i < team_size_; ++i) {
    Core& target = *cores_[i];
    if (&target == &core) continue;
    CoreSide& s = side_[i];
    if (target.asleep && s.wait == Wait::kDispatch) {
      s.arg = fork_arg_;
      WakeCore(target, at, value);
    } else {
      s.mailbox.push_back({value, fork_arg_});
    }
  }
}

uint32_t Cluster::DmaRead(Core& core, uint32_t) {
  const DmaCommand& cmd = side_[core.id()].dma;
  const std::string problem = Dma::Check(cmd);
  if (!problem.empty()) core.Raise(FaultKind::kMemory, problem);
  schedule_changed_ = true;
  return dma_.Push(cmd, core.time + timing::kPeriphAccess);
}

void Cluster::DmaWrite(Core& core, uint32_t addr, uint32_t value) {
  CoreSide& s = side_[core.id()];
  switch (addr) {
    case GAP8_DMA_EXT:
      s.dma.ext = value;
      return;
    case GAP8_DMA_LOC:
      s.dma.loc = value;
      return;
    case GAP8_DMA_SIZE:
      s.dma.size = value;
      return;
    case GAP8_DMA_DIR:
      s.dma.dir = value;
      return;
    case GAP8_DMA_STRIDE:
      s.dma.stride = value;
      return;
    case GAP8_DMA_LENGTH:
      s.dma.length = value;
      return;
    default:  // GAP8_DMA_WAIT
      if (dma_.Done(value)) return;
      s.wait_dma_id = value;
      SleepOn(core, Wait::kDma);
  }
}

}  // namespace gap8
