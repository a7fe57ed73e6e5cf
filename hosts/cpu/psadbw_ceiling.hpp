// The ceiling of the SAD work: back-to-back independent psadbw on L1-resident data, at each
// width, in bytes compared per TSC cycle. Each width is in its own file, compiled with the flags
// of the ISA table row whose `ceiling` column names it (hosts/cpu/CMakeLists.txt).
#pragma once
#include <cstdint>

namespace pxflow::cpu {

// Runs `rounds` x 12 independent psadbw of the given width, each on 64 L1-resident bytes
// (a 768-byte buffer); returns a value that depends on every result so none is optimised away.
std::uint64_t psadbw_xmm(const std::uint8_t* data, std::int64_t rounds);
std::uint64_t psadbw_ymm(const std::uint8_t* data, std::int64_t rounds);
std::uint64_t psadbw_zmm(const std::uint8_t* data, std::int64_t rounds);

// Bytes psadbw-compared per TSC cycle by the widest psadbw this CPU has (and may use: the ISA
// mask applies), the fastest of many trials since others may share the machine.
struct Ceiling {
  const char* width = "none";
  double bytes_per_cycle = 0;  // 0 when no x86 SIMD path is available
};
Ceiling measure_ceiling();

// The bound of SPEC §6's SAD work for one frame: every POI searched and refined, the feature
// test left out (364,544 bytes for px4flow-64), in bytes.
double sad_bytes_per_frame(long pois, int search_radius);

}  // namespace pxflow::cpu
