#include "gap8_backend.hpp"

#include <bit>
#include <cstring>

#include "counted.hpp"
#include "errors.hpp"
#include "estimate.hpp"
#include "grid.hpp"
#include "pxflow_version.h"

namespace pxflow {
namespace {

// The kernel's estimate must be the host's, bit for bit (SPEC §5: the same float operations in
// the same order, soft-float on the core).
void check_estimate(std::span<const PoiRecord> records, const Params& p,
                    const pxflow_gap8_result& result, std::size_t pair) {
  const pxflow_estimate& kernel = result.estimate;
  const FrameResult host = estimate_flow(records, p);
  if (std::bit_cast<std::uint32_t>(host.flow_x) != std::bit_cast<std::uint32_t>(kernel.flow_x) ||
      std::bit_cast<std::uint32_t>(host.flow_y) != std::bit_cast<std::uint32_t>(kernel.flow_y) ||
      host.quality != kernel.quality || host.meancount != kernel.meancount)
    throw BackendError("gap8: the kernel's estimate of pair " + std::to_string(pair) + " (" +
                       std::to_string(kernel.flow_x) + ", " + std::to_string(kernel.flow_y) +
                       ", quality " + std::to_string(kernel.quality) +
                       ") differs from estimate_flow of its records (" +
                       std::to_string(host.flow_x) + ", " + std::to_string(host.flow_y) +
                       ", quality " + std::to_string(host.quality) + ")");
}

}  // namespace

Gap8Backend::Gap8Backend(Gap8Variant variant, gap8_host::RunOptions options, int host_threads)
    : variant_(variant), runner_(variant), options_(options), pool_(host_threads) {}

void Gap8Backend::run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
                      OpCounts& counts) {
  last_time_.reset();
  const std::size_t pois = poi_count(p);
  if (out.size() != pairs.size() * pois) throw BackendError("gap8: output size mismatch");
  gap8_host::BatchStats stats = runner_.run(pairs, p, out, options_, &pool_);
  for (std::size_t i = 0; i < pairs.size(); ++i)
    check_estimate(out.subspan(i * pois, pois), p, stats.pairs[i], i);
  counts += gap8_counts(variant_, out, p, pairs.size());
  const double cycles = static_cast<double>(stats.cycles);
  last_time_ = DeviceTime{.source = "gap8-model-cycles",
                          .ns = cycles / kGap8ClockHz * 1e9,
                          .cycles = cycles,
                          .exact = true};
  last_stats_ = std::move(stats);
}

// RI5CY's Xpulp SIMD instructions take 4 bytes of each operand, one instruction per cycle, and
// GAP8 has no SAD instruction (a 4-byte SAD is 4 of them, flow_simd.h; 2 in the fast variant's
// algebra, flow_search_fast.c): no kernel compares more than 4 bytes per cycle per core.
std::optional<Backend::DeviceBound> Gap8Backend::device_bound(const Params& p) const {
  const int cores = options_.cores;
  return DeviceBound{
      "the SAD work at 4 bytes per cycle on each of " + std::to_string(cores) +
          " cores (one 4-byte Xpulp SIMD instruction per cycle, no load)",
      "cycles",
      sad_bytes_per_frame(static_cast<long>(poi_count(p)), p.search_radius) / (4.0 * cores)};
}

Backend::Description Gap8Backend::describe() const {
  return {std::string("kernels/gap8 ") + gap8_variant(variant_).name + " on " +
              counted(options_.cores, "core") + ", TCDM contention " +
              (options_.contention ? "on" : "off") + ", POIs " +
              (options_.chunked ? "in chunks" : "round robin"),
          "GAP8 cluster cycle model at " + std::to_string(static_cast<int>(kGap8ClockHz / 1e6)) +
              " MHz",
          std::string("gap8_model ") + PXFLOW_GAP8_MODEL_VERSION};
}

OpCounts gap8_counts(Gap8Variant variant, std::span<const PoiRecord> records, const Params& p,
                     std::size_t pairs) {
  OpCounts c;
  c.counted = true;
  const std::uint64_t candidates = (2 * p.search_radius + 1) * (2 * p.search_radius + 1);
  std::uint64_t accepted = 0;
  for (const PoiRecord& r : records) {
    c.sad_ops += 6;
    if (r.status != kDropped) c.sad_ops += 16 * candidates;
    if (r.status == kAccepted) ++accepted;
  }
  c.sad_ops += 128 * accepted;
  switch (gap8_variant(variant).half_pixel) {
    case Gap8HalfPixel::kPerPixel:
      c.interpolations = 768 * accepted;
      break;
    case Gap8HalfPixel::kLocalPlanes:
      c.interpolations = 300 * accepted;
      break;
    case Gap8HalfPixel::kGlobalPlanes:
      c.interpolations = std::uint64_t{3} * p.width * p.height * static_cast<std::uint64_t>(pairs);
      break;
  }
  return c;
}

}  // namespace pxflow
