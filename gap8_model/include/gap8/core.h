// One RI5CY-class cluster core: RV32IMC plus PULPv2 (Xpulp), with the pipeline hazards and
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
    Decoded* slot;
    if (Memory::InL2(pc_)) {  // where code almost always is: a slot, no null test
      slot = mem_.L2CodeSlot(pc_);
    } else {
      slot = mem_.CodeSlot(pc_);
      if (!slot) RaiseFetchFault();
    }
    if (slot->op == Op::kUndecoded) *slot = Decode(mem_.FetchBits(pc_));
    return *slot;
  }
  // The decode-cache slot of the instruction at pc, not decoded (op kUndecoded: call Fetch, which
  // decodes it or, for a pc outside L1 and L2, throws). A slot stays the one of its pc: a store
  // over its bytes marks it kUndecoded again. The cluster's issue loops keep it from one
  // instruction to the next.
  const Decoded* CodeSlot() const {
    if (Memory::InL2(pc_)) return mem_.L2CodeSlot(pc_);
    const Decoded* slot = mem_.CodeSlot(pc_);
    return slot ? slot : &kNoSlot;
  }
  // True for the slot CodeSlot gives for a pc outside L1 and L2 (its Fetch throws).
  static bool IsNoSlot(const Decoded* slot) { return slot == &kNoSlot; }
  // True when d, issued now, reads and writes only this core's registers, pc and counters and
  // cannot fault: no memory access, hardware-loop set-up or illegal instruction, and not the last
  // instruction of an active hardware loop (there a jump, or a one-instruction body, faults).
  bool OwnStateOnly(const Decoded& d) const {
    return (d.access & kAccessOwnState) && !(loops_armed_ && AtActiveLoopEnd());
  }
  // True when executing d, whose access address is addr (AccessAddress), cannot end the run
  // (exit, fault) or rewrite code: OwnStateOnly, or a TCDM load, or a store when L1 holds no
  // code, wholly inside L1 and not at a loop end.
  bool CannotStopOrRewrite(const Decoded& d, uint32_t addr) const {
    if (d.access & kAccessOwnState) return !(loops_armed_ && AtActiveLoopEnd());
    const bool store = (d.access & kAccessStore) != 0;
    return d.tcdm && addr - GAP8_L1_BASE <= GAP8_L1_SIZE - 4 && !(store && mem_.l1_has_code()) &&
           !(loops_armed_ && AtActiveLoopEnd());
  }
  // Before issuing d: the cycles d must wait for the previous instruction's result (load-use,
  // mul-use, jump-register; timing.h), 0 when none. A stall consumes the hazard and bumps its
  // counter.
  uint32_t TakeHazardStall(const Decoded& d) {
    // One test decides: a load or mul result read by d, or an ALU result read by a jalr.
    const uint32_t jalr_reads = d.op == Op::kJalr ? d.src_mask : 0u;
    if (((d.src_mask & data_hazard_mask_) | (jalr_reads & jump_hazard_mask_)) == 0) return 0;
    return ConsumeHazardStall();
  }
  // Bit b set when d accesses TCDM bank b this cycle; 0 when d makes no TCDM access.
  // Branch-free: the cluster calls it for every core in every shared cycle.
  uint32_t TcdmBankBit(const Decoded& d) const { return TcdmBankBit(d, AccessAddress(d)); }
  static uint32_t TcdmBankBit(const Decoded& d, uint32_t addr) {
    const uint32_t in_l1 = addr - GAP8_L1_BASE < GAP8_L1_SIZE;
    return (in_l1 & d.tcdm) << ((addr >> 2) & (GAP8_L1_BANKS - 1));
  }
  // Address of a load or store (post-increment forms use rs1 unmodified). x0 reads 0, so an
  // access without an offset register adds regs_[0]; one without an immediate adds 0.
  uint32_t AccessAddress(const Decoded& d) const {
    return regs_[d.rs1] + regs_[d.offset_reg] + static_cast<uint32_t>(d.access_imm);
  }
  // Executes d (the instruction at pc) and returns its cost in cycles. Throws Fault.
  uint32_t Execute(const Decoded& d);
  // The same, inline (src/core_execute_inline.h): the cluster's issue loops use it.
  uint32_t ExecuteInline(const Decoded& d);
  // Fetch + Execute, ignoring hazards: the architectural step the differential test compares.
  uint32_t Step() { return Execute(Fetch()); }

  // Scheduling state owned by the Cluster.
  uint64_t time = 0;   // cycle at which the next instruction may issue
  uint64_t slept = 0;  // cycles spent asleep (not active)
  bool asleep = false;
  uint32_t prefetch_base = ~0u;  // line held by the prefetch buffer (none at start)
  uint8_t wake_rd = 0;           // register receiving the value delivered at wake-up
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

  // The result of the instruction just executed (register rd) is pending, as `kind`: a load or
  // mul result stalls any reader, an ALU result only a jalr.
  void SetHazardBit(Hazard kind, uint32_t bit) {  // bit: Decoded::rd_bit (x0 never stalls)
    hazard_ = kind;
    data_hazard_mask_ = (kind == Hazard::kLoad || kind == Hazard::kMul) ? bit : 0u;
    jump_hazard_mask_ = kind == Hazard::kAlu ? bit : 0u;
  }
  void ClearHazard() { SetHazardBit(Hazard::kNone, 0); }
  [[noreturn]] void RaiseFetchFault() const;
  [[noreturn]] void RaiseUnmapped(const char* access, uint32_t bytes, const char* where,
                                  uint32_t addr) const;
  uint32_t ConsumeHazardStall();
  uint32_t LoadOutsideL1(uint32_t addr, uint32_t bytes, bool misaligned, uint32_t* cost);
  void StoreOutsideL1(uint32_t addr, uint32_t bytes, bool misaligned, uint32_t value,
                      uint32_t* cost);
  uint32_t ExecuteMemory(const Decoded& d);
  uint32_t ExecuteMulDiv(const Decoded& d);
  uint32_t ExecuteHwLoopSetup(const Decoded& d);
  uint32_t ExecuteBranch(const Decoded& d, bool taken);
  uint32_t ExecuteJump(const Decoded& d, uint32_t a, uint32_t imm);
  uint32_t NextSequentialPc(uint32_t next);
  bool AtActiveLoopEnd() const;
  [[noreturn]] void RaiseHwLoop(const char* rule) const;

  static constexpr Decoded kNoSlot{};  // CodeSlot outside L1 and L2: op kUndecoded

  int id_;
  Memory& mem_;
  Cluster* cluster_;
  std::array<uint32_t, 32> regs_{};
  uint32_t pc_ = 0;
  const Decoded* current_ = nullptr;
  Hazard hazard_ = Hazard::kNone;
  uint32_t data_hazard_mask_ = 0;  // bit of a pending load or mul result, else 0
  uint32_t jump_hazard_mask_ = 0;  // bit of a pending ALU result (jalr stalls on it), else 0
  bool loops_armed_ = false;
  std::array<uint32_t, 2> loop_start_{}, loop_end_{}, loop_count_{};
  std::array<uint64_t, GAP8_EVT_COUNT> events_{};
  PerfCounters perf_;
};

// True when the instruction at pc is the last one of an active hardware loop.
inline bool Core::AtActiveLoopEnd() const {
  return (loop_count_[0] != 0 && pc_ == loop_end_[0]) ||
         (loop_count_[1] != 0 && pc_ == loop_end_[1]);
}

// The pc after a non-jumping instruction: a hardware loop's end sends it back to the start.
inline uint32_t Core::NextSequentialPc(uint32_t next) {
  if (!loops_armed_) return next;
  for (int l = 0; l < 2; ++l) {  // loop 0 is the inner loop: it has priority
    if (loop_count_[l] != 0 && pc_ == loop_end_[l]) {
      if (loop_start_[l] == loop_end_[l])
        RaiseHwLoop("a hardware loop body must have at least 2 instructions");
      if (--loop_count_[l] != 0) return loop_start_[l];
    }
  }
  loops_armed_ = loop_count_[0] != 0 || loop_count_[1] != 0;
  return next;
}

}  // namespace gap8
