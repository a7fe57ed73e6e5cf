// How a batch of frame pairs is laid out in the storage buffers and split into chunks and
// dispatches that respect the device's limits. Pure arithmetic, testable without a device.
#pragma once
#include <cstddef>
#include <cstdint>

#include "params.hpp"

namespace pxflow::vk {

struct BatchLayout {
  std::uint32_t words_per_frame = 0;  // ceil(W*H / 4) + 1 spare word for the funnel read
  std::uint64_t pair_bytes = 0;       // prev + next
  std::size_t pois_per_pair = 0;
  std::uint64_t record_bytes_per_pair = 0;
  std::uint64_t work_per_pair = 0;  // pixel differences of the integer search, all POIs
};

BatchLayout batch_layout(const Params& p);

// Limits a chunk must respect.
struct ChunkLimits {
  std::uint64_t max_buffer_bytes = 0;  // device limits (vulkan_backend.cpp) and the cap
  std::uint64_t max_work = 0;          // keeps one submission short (fence timeout, GPU watchdog)
};

// Pairs per chunk: as many as fit both buffers and the work cap, at least 1 when one pair fits
// the buffers; 0 when a single pair does not fit.
std::size_t pairs_per_chunk(const BatchLayout& layout, const ChunkLimits& limits);

}  // namespace pxflow::vk
