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

// The widest psadbw this CPU has and may use (the ISA mask applies): "xmm", "ymm", "zmm", or
// "none" when no x86 SIMD path is available.
const char* ceiling_width();

// Bytes psadbw-compared per TSC cycle by `threads` threads each running back-to-back psadbw of
// ceiling_width() at once, summed (two threads on the two hyperthreads of one core share its
// ports); each thread's fastest of many trials, counted only while every thread still runs, since
// others may share the machine. 0 when the width is "none".
double measure_ceiling(int threads);

// The bound of SPEC §6's SAD work for one frame: every POI searched and refined, the feature
// test left out (364,544 bytes for px4flow-64), in bytes.
double sad_bytes_per_frame(long pois, int search_radius);

}  // namespace pxflow::cpu
