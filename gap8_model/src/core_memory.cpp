// Loads and stores outside TCDM (L2 through the cluster bridge, the cluster's peripherals) with
// their costs; the TCDM path and the post-increment / register-offset forms are inline in
// core_execute_inline.h (Core::ExecuteMemory).
#include "core_execute_inline.h"
#include "gap8/cluster.h"

namespace gap8 {

using execute_detail::ReadBytes;
using execute_detail::WriteBytes;

// Out of line and cold: the message is built only for a fault.
[[gnu::cold, gnu::noinline]] void Core::RaiseUnmapped(const char* access, uint32_t bytes,
                                                      const char* where, uint32_t addr) const {
  Raise(FaultKind::kMemory, access + std::to_string(bytes) + where + Hex(addr));
}

// LD is already counted; *cost holds the TCDM cost.
uint32_t Core::LoadOutsideL1(uint32_t addr, uint32_t bytes, bool misaligned, uint32_t* cost) {
  uint32_t raw = 0;
  if (uint8_t* q = mem_.L2Span(addr, bytes)) {
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
  return raw;
}

// ST is already counted; *cost holds the TCDM cost.
void Core::StoreOutsideL1(uint32_t addr, uint32_t bytes, bool misaligned, uint32_t value,
                          uint32_t* cost) {
  if (uint8_t* q = mem_.L2Span(addr, bytes)) {
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

}  // namespace gap8
