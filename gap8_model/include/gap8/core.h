// One RI5CY-class cluster core: RV32IMC plus the Xpulp subset, with the pipeline hazards and
// per-instruction costs of include/gap8/timing.h. The Cluster schedules cores; a Core alone can
// also be stepped instruction by instruction (the differential test does that).
#pragma once

#include <array>
#include <cstdint>

#include "gap8/decoded.h"
#include "gap8/fault.h"
#include "gap8/memory.h"
#include "gap8/perf.h"

namespace gap8 {

class Cluster;

class Core {
 public:
  Core(int id, Memory& memory, Cluster* cluster) : id_(id), mem_(memory), cluster_(cluster) {}

  int id() const { return id_; }
  uint32_t pc() const { return pc_; }
  void set_pc(uint32_t pc) { pc_ = pc; }
  uint32_t reg(int r) const { return regs_[r]; }
  void set_reg(int r, uint32_t v) {
    if (r != 0) regs_[r] = v;
  }

  // The decoded instruction at pc; throws Fault when pc is outside L1 and L2.
  const Decoded& Fetch() {
    Decoded* slot = mem_.CodeSlot(pc_);
    if (!slot) RaiseFetchFault();
    if (slot->op == Op::kUndecoded) *slot = Decode(mem_.FetchBits(pc_));
    return *slot;
  }
  // Before issuing d: true (and the hazard consumed, its counter bumped) when d must wait a
  // cycle for the previous instruction's result (load-use, mul-use, jump-register).
  bool TakeHazardStall(const Decoded& d) {
    if (hazard_rd_ == 0 || hazard_ == Hazard::kNone) return false;
    return TakeHazardStallSlow(d);
  }
  // The TCDM bank d will access this cycle, or -1 when d makes no TCDM access.
  int TcdmBank(const Decoded& d) const;
  // Executes d (the instruction at pc) and returns its cost in cycles. Throws Fault.
  uint32_t Execute(const Decoded& d);
  // Fetch + Execute, ignoring hazards: the architectural step the differential test compares.
  uint32_t Step() { return Execute(Fetch()); }

  // Scheduling state owned by the Cluster.
  uint64_t time = 0;   // cycle at which the next instruction may issue
  uint64_t slept = 0;  // cycles spent asleep (not active)
  bool asleep = false;
  uint8_t wake_rd = 0;  // register receiving the value delivered at wake-up
  // Called by a blocking peripheral access; the access's load sets wake_rd.
  void Sleep() {
    asleep = true;
    wake_rd = 0;
  }
  void Wake(uint64_t at, uint32_t value);

  uint64_t& event(int e) { return events_[e]; }
  // Free-running totals of every PMSIS event (CYCLES and ACTIVE_CYCLES derived from time).
  EventTotals Totals() const;
  PerfCounters& perf() { return perf_; }

  // The instruction being executed (valid during Execute).
  const Decoded* current() const { return current_; }

  [[noreturn]] void Raise(FaultKind kind, const std::string& what) const;

 private:
  enum class Hazard : uint8_t { kNone, kLoad, kMul, kAlu };

  [[noreturn]] void RaiseFetchFault() const;
  bool TakeHazardStallSlow(const Decoded& d);
  uint32_t Load(const Decoded& d, uint32_t addr, uint32_t* cost);
  void Store(const Decoded& d, uint32_t addr, uint32_t value, uint32_t* cost);
  uint32_t ExecuteMemory(const Decoded& d);
  uint32_t ExecuteMulDiv(const Decoded& d);
  uint32_t ExecuteXpulp(const Decoded& d);
  uint32_t ExecuteHwLoopSetup(const Decoded& d);
  uint32_t ExecuteBranch(const Decoded& d, bool taken);
  uint32_t NextSequentialPc(uint32_t next);

  int id_;
  Memory& mem_;
  Cluster* cluster_;
  std::array<uint32_t, 32> regs_{};
  uint32_t pc_ = 0;
  const Decoded* current_ = nullptr;
  Hazard hazard_ = Hazard::kNone;
  uint8_t hazard_rd_ = 0;
  bool loops_armed_ = false;
  std::array<uint32_t, 2> loop_start_{}, loop_end_{}, loop_count_{};
  std::array<uint64_t, GAP8_EVT_COUNT> events_{};
  PerfCounters perf_;
};

}  // namespace gap8
