// Loads and stores (RV32I and the PULP post-increment / register-offset forms) with their costs:
// TCDM, L2 through the cluster bridge, or the cluster's peripherals.
#include <cstring>

#include "gap8/cluster.h"
#include "gap8/core.h"
#include "gap8/timing.h"

namespace gap8 {
namespace {

uint32_t AccessBytes(uint8_t width) { return 1u << (width & 3u); }

// Fixed-size copies, so the compiler emits plain moves instead of a memcpy call.
uint32_t ReadBytes(const uint8_t* p, uint32_t bytes) {
  if (bytes == 4) {
    uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
  }
  if (bytes == 2) {
    uint16_t v;
    std::memcpy(&v, p, 2);
    return v;
  }
  return *p;
}

void WriteBytes(uint8_t* p, uint32_t value, uint32_t bytes) {
  if (bytes == 4) {
    std::memcpy(p, &value, 4);
  } else if (bytes == 2) {
    const uint16_t v = static_cast<uint16_t>(value);
    std::memcpy(p, &v, 2);
  } else {
    *p = static_cast<uint8_t>(value);
  }
}

uint32_t Extend(uint32_t raw, uint8_t width) {
  switch (width) {
    case 0:
      return static_cast<uint32_t>(static_cast<int8_t>(raw));
    case 1:
      return static_cast<uint32_t>(static_cast<int16_t>(raw));
    default:
      return raw;  // lw, lbu, lhu: the raw bytes, zero-extended
  }
}

}  // namespace

// Out of line and cold, so that Load and Store stay small enough to inline into ExecuteMemory.
[[gnu::cold, gnu::noinline]] void Core::RaiseUnmapped(const char* access, uint32_t bytes,
                                                      const char* where, uint32_t addr) const {
  Raise(FaultKind::kMemory, access + std::to_string(bytes) + where + Hex(addr));
}

inline uint32_t Core::Load(const Decoded& d, uint32_t addr, uint32_t* cost) {
  const uint32_t bytes = AccessBytes(d.width);
  const bool misaligned = (addr & (bytes - 1)) != 0;
  events_[GAP8_EVT_LD] += misaligned ? 2 : 1;
  uint32_t raw = 0;
  if (uint8_t* p = mem_.L1Span(addr, bytes)) {
    raw = ReadBytes(p, bytes);
    *cost = timing::kLoadStore + (misaligned ? timing::kMisaligned : 0);
  } else if (uint8_t* q = mem_.L2Span(addr, bytes)) {
    raw = ReadBytes(q, bytes);
    *cost = timing::kLoadStore + timing::kL2Latency + (misaligned ? timing::kMisaligned : 0);
    events_[GAP8_EVT_LD_EXT] += misaligned ? 2 : 1;
    events_[GAP8_EVT_LD_EXT_CYC] += timing::kL2Latency;  // GVSOC counts the wait
  } else if (cluster_ && cluster_->IsPeripheral(addr, bytes)) {
    uint32_t extra = 0;
    raw = cluster_->PeripheralRead(*this, addr, &extra);
    *cost = timing::kPeriphAccess + extra;
    if (Cluster::IsExternalPeripheral(addr)) {  // GVSOC's router counts the answer's latency
      ++events_[GAP8_EVT_LD_EXT];
      events_[GAP8_EVT_LD_EXT_CYC] += extra;
    }
  } else {
    RaiseUnmapped("load of ", bytes, " bytes from unmapped address ", addr);
  }
  return Extend(raw, d.width);
}

inline void Core::Store(const Decoded& d, uint32_t addr, uint32_t value, uint32_t* cost) {
  const uint32_t bytes = AccessBytes(d.width);
  const bool misaligned = (addr & (bytes - 1)) != 0;
  events_[GAP8_EVT_ST] += misaligned ? 2 : 1;
  if (uint8_t* p = mem_.L1Span(addr, bytes)) {
    WriteBytes(p, value, bytes);
    mem_.InvalidateCode(addr, bytes);  // L1 may hold code too
    *cost = timing::kLoadStore + (misaligned ? timing::kMisaligned : 0);
  } else if (uint8_t* q = mem_.L2Span(addr, bytes)) {
    WriteBytes(q, value, bytes);
    mem_.InvalidateCode(addr, bytes);
    *cost = timing::kLoadStore + timing::kL2Latency + (misaligned ? timing::kMisaligned : 0);
    events_[GAP8_EVT_ST_EXT] += misaligned ? 2 : 1;
    events_[GAP8_EVT_ST_EXT_CYC] += timing::kL2Latency;
  } else if (cluster_ && cluster_->IsPeripheral(addr, bytes)) {
    *cost = timing::kPeriphAccess;
    cluster_->PeripheralWrite(*this, addr, value);
    events_[GAP8_EVT_ST_EXT] += Cluster::IsExternalPeripheral(addr);
  } else {
    RaiseUnmapped("store of ", bytes, " bytes to unmapped address ", addr);
  }
}

uint32_t Core::ExecuteMemory(const Decoded& d) {
  const uint32_t addr = AccessAddress(d);
  uint32_t cost = 0;
  const uint32_t next = pc_ + d.size;
  if (d.access & kAccessStore) {
    Store(d, addr, regs_[d.rs2], &cost);
    ClearHazard();
    if (d.op == Op::kStorePostImm) regs_[d.rs1] = addr + static_cast<uint32_t>(d.imm);
    if (d.op == Op::kStorePostReg) regs_[d.rs1] = addr + regs_[d.rd];
  } else {
    const uint32_t value = Load(d, addr, &cost);
    if (d.op == Op::kLoadPostImm) regs_[d.rs1] = addr + static_cast<uint32_t>(d.imm);
    if (d.op == Op::kLoadPostReg) regs_[d.rs1] = addr + regs_[d.rs2];
    regs_[d.rd] = value;  // written last: with rd == rs1 the loaded value wins
    SetHazardBit(Hazard::kLoad, d.rd_bit);
    if (asleep) ClearHazard();  // a blocking peripheral read delivers at wake-up
    if (asleep) wake_rd = d.rd;
  }
  regs_[0] = 0;
  pc_ = NextSequentialPc(next);
  return cost;
}

}  // namespace gap8
