// Guard zones: sentinel-filled bytes right before and after an output that a device writes (an
// OpenCL or Vulkan buffer, the GAP8 model's result area, the dut protocol's record stream),
// checked after every run. ASan cannot see a GPU's or a model's writes; these can. A hit is the
// backend's failure: BackendError "wrote past its output (N bytes after record K)".
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>

#include "errors.hpp"
#include "record.hpp"

namespace pxflow {

inline constexpr std::uint8_t kGuardByte = 0x5a;  // not the check's unwritten-record sentinel
inline constexpr std::size_t kGuardRecords = 4;   // each side
inline constexpr std::size_t kGuardBytes = kGuardRecords * sizeof(PoiRecord);

inline void fill_guard(std::span<std::uint8_t> zone) {
  std::memset(zone.data(), kGuardByte, zone.size());
}

// "wrote past its output (N bytes after record K)": the zone after an output of `records`
// records (K = records - 1, its last) has a changed byte, the farthest N bytes past the output's
// end. `who` starts the message ("opencl", "gap8 model").
inline void check_guard_after(std::span<const std::uint8_t> zone, std::size_t records,
                              const std::string& who) {
  for (std::size_t i = zone.size(); i-- > 0;)
    if (zone[i] != kGuardByte)
      throw BackendError(who + ": wrote past its output (" + std::to_string(i + 1) +
                         " bytes after record " + std::to_string(records ? records - 1 : 0) + ")");
}

// The zone right before the output: "wrote before its output (N bytes before record 0)".
inline void check_guard_before(std::span<const std::uint8_t> zone, const std::string& who) {
  for (std::size_t i = 0; i < zone.size(); ++i)
    if (zone[i] != kGuardByte)
      throw BackendError(who + ": wrote before its output (" + std::to_string(zone.size() - i) +
                         " bytes before record 0)");
}

}  // namespace pxflow
