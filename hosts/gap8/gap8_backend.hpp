// The GAP8 backends (gap8-<variant>, gap8_variants.hpp): the kernel of kernels/gap8 on the
// cluster model, all 8 cores, TCDM contention on. `host_threads` host workers simulate
// the batch's cluster runs side by side (0 = every core); the results do not depend on it. Besides
// the records, each run checks the kernel's own soft-float estimate against estimate_flow() of its
// records.
#pragma once
#include <optional>
#include <string>

#include "backend.hpp"
#include "gap8_flow_runner.hpp"
#include "gap8_variants.hpp"

namespace pxflow {

class Gap8Backend : public Backend {
 public:
  Gap8Backend(Gap8Variant variant, gap8_host::RunOptions options, int host_threads = 1);

  void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
           OpCounts& counts) override;
  std::string unsupported(const Params& p) const override { return runner_.unsupported(p); }
  std::optional<DeviceTime> last_device_time() const override { return last_time_; }
  // The variant's kernel, the cluster it runs on and the model's version (git tree ids).
  Description describe() const override;
  // The SAD work at one 4-byte SIMD instruction per cycle on each of the cluster's cores
  // (docs/harness.md, "The bound of every row").
  std::optional<DeviceBound> device_bound(const Params& p) const override;

  // The model's statistics of the last run() (per pair and per core).
  const gap8_host::BatchStats& last_stats() const { return last_stats_; }

 private:
  Gap8Variant variant_;
  gap8_host::FlowRunner runner_;
  gap8_host::RunOptions options_;
  ThreadPool pool_;
  gap8_host::BatchStats last_stats_;
  std::optional<DeviceTime> last_time_;
};

// The model's clock (the paper's operating point): cycles to nanoseconds.
inline constexpr double kGap8ClockHz = 50e6;

// Work of one batch as docs/counting.md charges it, derived from the records (the kernel does
// exactly this work): SAD operations, and the variant's interpolations.
OpCounts gap8_counts(Gap8Variant variant, std::span<const PoiRecord> records, const Params& p,
                     std::size_t pairs);

}  // namespace pxflow
