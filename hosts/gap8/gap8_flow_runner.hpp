// Runs the GAP8 flow kernel (kernels/gap8) on the cluster model: loads the embedded ELF once,
// then per run builds a fresh cluster from that image, writes the parameter block and the frames
// into L2, runs, and reads records, the kernel's own estimate and the counters back.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "flow_abi.h"
#include "frame.hpp"
#include "gap8/perf.h"
#include "gap8_variants.hpp"
#include "params.hpp"
#include "record.hpp"
#include "thread_pool.hpp"

namespace pxflow::gap8_host {

struct RunOptions {
  int cores = 8;           // cluster size and team size, 1..8
  bool contention = true;  // TCDM bank conflicts modelled
  bool chunked = false;    // POIs split in contiguous chunks instead of round robin
  // Tests only: after the run, a byte stored this many bytes (1-based) past the end of the L2
  // or L1 records, a planted overrun the guard zones must report.
  std::uint32_t plant_past_l2_records = 0, plant_past_l1_records = 0;
};

// What one batch cost on the model, and what the kernel reported per pair.
struct BatchStats {
  std::uint64_t cycles = 0;               // cluster cycles, every run of the batch
  std::vector<pxflow_gap8_result> pairs;  // per pair: estimate and cycle breakdown
  std::vector<gap8::EventTotals> cores;   // per core: counters summed over the runs
};

struct ChunkLayout;  // one cluster run's areas and guard zones (gap8_flow_runner.cpp)

class FlowRunner {
 public:
  // Throws BackendError when the variant's image is missing or cannot be loaded.
  explicit FlowRunner(Gap8Variant variant);

  // Empty when a problem of these parameters fits L1 and L2; else the limit it is outside.
  std::string unsupported(const Params& p) const;

  // Writes poi_count(p) records per pair into `out`. Throws BackendError on a fault, a non-zero
  // exit status or an unsupported problem. A batch larger than L2 holds runs as several
  // independent cluster runs ("chunks"); with a pool they are simulated side by side on the
  // host. Records, results and cycle totals do not depend on the pool: each chunk is its own
  // fresh cluster, and the totals are summed in chunk order.
  BatchStats run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
                 const RunOptions& options, ThreadPool* pool = nullptr) const;

 private:
  // Pairs per cluster run: as many as L2 holds beside the image.
  std::size_t pairs_per_chunk(const Params& p) const;
  // Where a chunk of `pairs` pairs puts its areas, and its parameter block.
  ChunkLayout chunk_layout(const Params& p, std::size_t pairs, const RunOptions& options) const;
  void run_chunk(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
                 const RunOptions& options, BatchStats& stats) const;

  std::vector<std::uint8_t> l2_image_;  // L2 bytes [L2 base, L2 base + size) after loading
  std::uint32_t entry_ = 0;
  std::uint32_t params_addr_ = 0;
  std::uint32_t io_base_ = 0;  // first free L2 byte after the image's .bss
  std::uint32_t l1_heap_start_ = 0, l1_heap_bytes_ = 0;
  std::uint32_t l1_next_addr_ = 0;  // the runtime's L1 allocator's next free byte (an L2 word)
  std::uint32_t planes_ = 0;        // full-frame planes of the variant in L1
};

}  // namespace pxflow::gap8_host
