// The ceiling of the SAD work: back-to-back independent psadbw on L1-resident data, at each
// width, in bytes compared per TSC cycle. Each width is in its own file with its own flags.
#pragma once
#include <cstdint>

namespace pxflow::cpu_bench {

// Runs `rounds` x 12 independent psadbw of the given width, each on 64 L1-resident bytes
// (a 768-byte buffer); returns a value that depends on every result so none is optimised away.
std::uint64_t psadbw_xmm(const std::uint8_t* data, std::int64_t rounds);
std::uint64_t psadbw_ymm(const std::uint8_t* data, std::int64_t rounds);
std::uint64_t psadbw_zmm(const std::uint8_t* data, std::int64_t rounds);

}  // namespace pxflow::cpu_bench
