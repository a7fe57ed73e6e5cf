// The cluster's memory-mapped peripherals: control, event unit, DMA and performance counters.
// Register addresses are in runtime/gap8_regs.h; costs in include/gap8/timing.h. The event unit
// follows GVSOC's eu_v3 (gap_sdk gvsoc/gvsoc_gap/models/pulp/event_unit/eu_v3_impl.cpp), the
// DMA's register side GVSOC's mchan_v6 (gvsoc/gvsoc_gap/models/pulp/mchan/mchan_v6_impl.cpp).
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

uint32_t Cluster::PeripheralRead(Core& core, uint32_t addr, uint32_t* extra) {
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
      return static_cast<uint32_t>(std::popcount(barrier_mask_));
    case GAP8_EU_BARRIER_MASK:
      return barrier_mask_;
    case GAP8_EU_DISPATCH_FIFO:
    case GAP8_EU_BARRIER_WAIT:
    case GAP8_EU_EVT_WAIT_CLEAR:
      return EventUnitRead(core, addr, extra);
    case GAP8_DMA_QUEUE:
    case GAP8_DMA_STATUS:
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
    case GAP8_EU_DISPATCH_TEAM:
    case GAP8_EU_DISPATCH_FIFO:
    case GAP8_EU_BARRIER_MASK:
    case GAP8_EU_BARRIER_TARGET:
    case GAP8_EU_EVT_MASK_OR:
    case GAP8_EU_EVT_MASK_AND:
      return EventUnitWrite(core, addr, value);
    case GAP8_DMA_QUEUE:
    case GAP8_DMA_STATUS:
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

// Reads that wait. GVSOC's wait_event: the answer comes kEuWaitLatency cycles after the event,
// plus kEuNoSleepLatency when the event is already there (the core then never sleeps).
uint32_t Cluster::EventUnitRead(Core& core, uint32_t addr, uint32_t* extra) {
  CoreSide& s = side_[core.id()];
  if (addr == GAP8_EU_BARRIER_WAIT) return BarrierWait(core, extra);
  if (addr == GAP8_EU_DISPATCH_FIFO) {
    // Dispatch_unit::req: a ready value is read at once, without the wait latency.
    if (s.dispatch.empty()) {
      SleepOn(core, Wait::kDispatch);
      return 0;
    }
    const uint32_t value = s.dispatch.front();
    s.dispatch.pop_front();
    return value;
  }
  // EVT_WAIT_CLEAR: an enabled event already set is consumed at once; else sleep.
  if (s.evt_status & s.evt_mask) {
    s.evt_status &= ~s.evt_mask;
    *extra = timing::kEuWaitLatency + timing::kEuNoSleepLatency;
    return 0;
  }
  SleepOn(core, Wait::kEvent);
  return 0;
}

// Barrier_unit EU_HW_BARR_TRIGGER_WAIT_CLEAR: the core's bit joins the status; when the status
// equals the trigger mask the barrier event goes to the target cores. The arriving core then
// waits like any event wait (it is a target, so its event is already there when it completes).
uint32_t Cluster::BarrierWait(Core& core, uint32_t* extra) {
  const uint32_t bit = 1u << core.id();
  if (!(barrier_mask_ & bit)) {
    core.Raise(FaultKind::kDeadlock, "barrier on a core outside the team of " +
                                         std::to_string(std::popcount(barrier_mask_)));
  }
  barrier_arrived_ |= bit;
  if (barrier_arrived_ != barrier_mask_) {
    SleepOn(core, Wait::kBarrier);
    return 0;
  }
  barrier_arrived_ = 0;
  for (auto& c : cores_) {
    const uint32_t b = 1u << c.id();
    if (&c != &core && (barrier_target_ & b) && c.asleep && side_[c.id()].wait == Wait::kBarrier)
      WakeCore(c, core.time, 0);
  }
  if (!(barrier_target_ & bit)) {
    SleepOn(core, Wait::kBarrier);  // not a target: nothing will wake it
    return 0;
  }
  *extra = timing::kEuWaitLatency + timing::kEuNoSleepLatency;
  return 0;
}

void Cluster::EventUnitWrite(Core& core, uint32_t addr, uint32_t value) {
  CoreSide& own = side_[core.id()];
  switch (addr) {
    case GAP8_EU_DISPATCH_TEAM:  // cores beyond this run's are dropped (GAP8 always has 8)
      dispatch_team_ = value & all_cores_;
      return;
    case GAP8_EU_BARRIER_MASK:
      barrier_mask_ = value & all_cores_;
      return;
    case GAP8_EU_BARRIER_TARGET:
      barrier_target_ = value & all_cores_;
      return;
    case GAP8_EU_EVT_MASK_OR:
      own.evt_mask |= value;
      return;
    case GAP8_EU_EVT_MASK_AND:
      own.evt_mask &= ~value;
      return;
    default:
      break;
  }
  // Dispatch push: every other team core gets the value; one waiting for it wakes with it.
  for (int i = 0; i < num_cores(); ++i) {
    Core& target = cores_[i];
    if (&target == &core || !((dispatch_team_ >> i) & 1u)) continue;
    CoreSide& s = side_[i];
    if (target.asleep && s.wait == Wait::kDispatch) {
      WakeCore(target, core.time, value);
    } else {
      s.dispatch.push_back(value);
    }
  }
}

// QUEUE read: allocate a counter (mchan::alloc_counter); STATUS read: counters with transfers in
// flight in bits 0..15, allocated counters in bits 16..31 (mchan::get_status).
uint32_t Cluster::DmaRead(Core& core, uint32_t addr) {
  if (addr == GAP8_DMA_STATUS) {
    uint32_t busy = 0;
    for (uint32_t i = 0; i < GAP8_DMA_COUNTERS; ++i) busy |= (dma_.Pending(i) != 0) << i;
    return busy | dma_allocated_ << 16;
  }
  const uint32_t free = ~dma_allocated_ & ((1u << GAP8_DMA_COUNTERS) - 1u);
  if (free == 0) {
    // GVSOC stalls the core until another frees a counter; the model stops the run instead.
    core.Raise(FaultKind::kMemory, "DMA: all 16 counters are allocated (transfers never freed)");
  }
  const uint32_t counter = static_cast<uint32_t>(std::countr_zero(free));
  dma_allocated_ |= 1u << counter;
  side_[core.id()].dma_counter = counter;
  return counter;
}

void Cluster::DmaWrite(Core& core, uint32_t addr, uint32_t value) {
  if (addr == GAP8_DMA_STATUS) {
    dma_allocated_ &= ~value;  // mchan::free_counters
    return;
  }
  DmaCommandWord(core, value);
}

// Mchan_channel::unpack_command: command, L1 address, L2 address, and for 2-D the strides word.
void Cluster::DmaCommandWord(Core& core, uint32_t value) {
  CoreSide& s = side_[core.id()];
  s.dma_words[s.dma_step++] = value;
  const uint32_t cmd = s.dma_words[0];
  const bool is_2d = (cmd & GAP8_DMA_CMD_2D) != 0;
  if (s.dma_step < (is_2d ? 4u : 3u)) return;
  s.dma_step = 0;
  DmaCommand c;
  c.size = cmd & GAP8_DMA_CMD_SIZE_MASK;
  c.dir = (cmd & GAP8_DMA_CMD_EXT2LOC) ? 1 : 0;
  c.loc = s.dma_words[1];
  c.ext = s.dma_words[2];
  if (is_2d) {
    c.stride = (s.dma_words[3] >> 16) & GAP8_DMA_2D_FIELD_MASK;
    c.length = s.dma_words[3] & GAP8_DMA_2D_FIELD_MASK;
    if (c.length == 0) core.Raise(FaultKind::kMemory, "DMA 2-D row length of 0 bytes");
  }
  if (!(cmd & GAP8_DMA_CMD_INCR)) core.Raise(FaultKind::kMemory, "DMA fixed-address mode");
  const std::string problem = Dma::Check(c);
  if (!problem.empty()) core.Raise(FaultKind::kMemory, problem);
  if (!((dma_allocated_ >> s.dma_counter) & 1u))
    core.Raise(FaultKind::kMemory, "DMA command on a counter that is not allocated");
  dma_.Push(c, core.time, s.dma_counter, static_cast<uint32_t>(core.id()),
            (cmd & GAP8_DMA_CMD_EVENT) != 0, (cmd & GAP8_DMA_CMD_BROADCAST) != 0);
  schedule_changed_ = true;
}

}  // namespace gap8
