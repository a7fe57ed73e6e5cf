#include "gap8_flow_runner.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "errors.hpp"
#include "gap8/cluster.h"
#include "gap8/elf_loader.h"
#include "gap8_kernel_elf.hpp"
#include "grid.hpp"
#include "guard_zone.hpp"
#include "spec_params.hpp"

namespace pxflow::gap8_host {
namespace {

// The records the kernel writes are PoiRecords (reference/spec_core.cpp asserts the layouts).
static_assert(sizeof(pxflow_gap8_params) == (1 + PXFLOW_PARAM_FIELDS + 6) * 4);

constexpr std::uint32_t kAlign = 8;
std::uint32_t align_up(std::uint64_t v) {
  return static_cast<std::uint32_t>((v + kAlign - 1) & ~std::uint64_t{kAlign - 1});
}

// The kernel ELF is embedded in pxflow and loaded from memory: no file is written or read.
gap8::ElfImage load_embedded(std::span<const std::uint8_t> elf, gap8::Memory& memory) {
  try {
    return gap8::LoadElfBytes("the embedded kernel ELF", elf, memory);
  } catch (const gap8::ElfError& e) {
    throw BackendError(std::string("gap8: ") + e.what());
  }
}

std::uint32_t symbol(const gap8::ElfImage& image, const std::string& name) {
  const auto it = image.symbols.find(name);
  if (it == image.symbols.end()) throw BackendError("gap8: kernel ELF has no symbol " + name);
  return it->second;
}

// The model's result areas sit between guard zones (guard_zone.hpp): in L2 a guard between the
// frames and the records, one between the records and the kernel's results, one after those; in
// L1 the free heap past the kernel's last allocation: the records are its last but for the fast
// variant's tables, which it places after them when they fit (kernels/gap8/fast_tables.c), so
// the whole free heap is filled and, after the run, checked from the allocator's final mark
// (gap8_model/runtime/runtime.c's l1_next) to the heap's end.
constexpr std::uint32_t kL2Guards = 3 * kGuardBytes;

std::uint32_t pair_io_bytes(const Params& p) {
  const std::uint64_t frame = std::uint64_t(p.width) * p.height;
  return align_up(2 * frame) + align_up(poi_count(p) * sizeof(PoiRecord)) +
         static_cast<std::uint32_t>(sizeof(pxflow_gap8_result));
}

}  // namespace

FlowRunner::FlowRunner(Gap8Variant variant) {
  const Gap8VariantInfo& info = gap8_variant(variant);
  const auto elf = gap8_kernel_elf(info.name);
  if (elf.empty()) throw BackendError(std::string("gap8: no kernel ELF for variant ") + info.name);
  gap8::Memory memory;
  const gap8::ElfImage image = load_embedded(elf, memory);
  entry_ = image.entry;
  params_addr_ = symbol(image, "pxflow_params");
  io_base_ = align_up(symbol(image, "__bss_end"));
  l1_heap_start_ = symbol(image, "__l1_heap_start");
  l1_heap_bytes_ = symbol(image, "__l1_heap_end") - l1_heap_start_;
  l1_next_addr_ = symbol(image, "l1_next");
  planes_ = info.half_pixel == Gap8HalfPixel::kGlobalPlanes ? 3 : 0;
  // Only the loaded part of L2 is copied into each new cluster: the rest is zero anyway.
  l2_image_.resize(io_base_ - GAP8_L2_BASE);
  memory.Read(GAP8_L2_BASE, l2_image_.data(), static_cast<std::uint32_t>(l2_image_.size()));
}

std::string FlowRunner::unsupported(const Params& p) const {
  const std::uint64_t frame = std::uint64_t(p.width) * p.height;
  const std::string what = planes_ ? "frames, planes and records" : "frames and records";
  if (frame > GAP8_L1_SIZE) return "does not fit L1: a frame alone is larger than the 64 KiB TCDM";
  const std::uint32_t need = align_up(
      pxflow_gap8_l1_bytes(p.width, p.height, static_cast<std::uint32_t>(poi_count(p)), planes_));
  if (need + kGuardBytes > l1_heap_bytes_)
    return "does not fit L1: " + what + " need " + std::to_string(need) + " bytes and " +
           std::to_string(kGuardBytes) + " of guard, the L1 heap beside 8 core stacks has " +
           std::to_string(l1_heap_bytes_);
  if (pair_io_bytes(p) + kL2Guards > GAP8_L2_BASE + GAP8_L2_SIZE - io_base_)
    return "does not fit L2";
  return {};
}

std::size_t FlowRunner::pairs_per_chunk(const Params& p) const {
  return (GAP8_L2_BASE + GAP8_L2_SIZE - io_base_ - kL2Guards) / pair_io_bytes(p);
}

BatchStats FlowRunner::run(std::span<const FramePair> pairs, const Params& p,
                           std::span<PoiRecord> out, const RunOptions& options,
                           ThreadPool* pool) const {
  if (const std::string why = unsupported(p); !why.empty()) throw BackendError("gap8: " + why);
  if (options.cores < 1 || options.cores > 8) throw BackendError("gap8: cores must be 1..8");
  const std::size_t pois = poi_count(p);
  const std::size_t per_chunk = pairs_per_chunk(p);
  const std::size_t chunks = (pairs.size() + per_chunk - 1) / per_chunk;
  std::vector<BatchStats> parts(chunks);
  auto one = [&](std::size_t c) {
    const std::size_t first = c * per_chunk, n = std::min(per_chunk, pairs.size() - first);
    parts[c].cores.assign(options.cores, gap8::EventTotals{});
    run_chunk(pairs.subspan(first, n), p, out.subspan(first * pois, n * pois), options, parts[c]);
  };
  if (pool && chunks > 1)
    pool->for_each(chunks, one);
  else
    for (std::size_t c = 0; c < chunks; ++c) one(c);

  BatchStats stats;
  stats.cores.assign(options.cores, gap8::EventTotals{});
  for (const BatchStats& part : parts) {
    stats.cycles += part.cycles;
    stats.pairs.insert(stats.pairs.end(), part.pairs.begin(), part.pairs.end());
    for (int c = 0; c < options.cores; ++c)
      for (std::size_t e = 0; e < part.cores[c].size(); ++e) stats.cores[c][e] += part.cores[c][e];
  }
  return stats;
}

// Where one cluster run ("chunk") puts its parameter block's areas in L2 and its records in L1,
// and the guard zones around them: the gaps between the L2 areas (up to the next area's start)
// and after the last, and the L1 heap past the records.
struct ChunkLayout {
  struct Zone {
    std::uint32_t at, bytes;
  };
  pxflow_gap8_params block{};
  std::size_t pairs = 0;
  std::uint32_t frame = 0, pois = 0, rec_bytes = 0;  // per pair: frame bytes, POIs, record bytes
  std::uint32_t l2_records_end = 0, l1_records_end = 0, l1_heap_end = 0;
  Zone before_l2{}, after_l2{}, after_results{}, free_l1{};
};

namespace {

// The frames of the chunk's pairs into L2, back to back: each pair's prev, then its next.
void write_frames(gap8::Memory& mem, const ChunkLayout& l, std::span<const FramePair> pairs,
                  const Params& p) {
  for (std::size_t i = 0; i < l.pairs; ++i) {
    for (int which = 0; which < 2; ++which) {
      const FrameView& f = which == 0 ? pairs[i].prev : pairs[i].next;
      std::uint32_t at = l.block.frames_l2 + static_cast<std::uint32_t>((2 * i + which) * l.frame);
      for (int y = 0; y < p.height; ++y, at += p.width) mem.Write(at, f.row(y), p.width);
    }
  }
}

void fill_guards(gap8::Memory& mem, const ChunkLayout& l) {
  const std::vector<std::uint8_t> sentinel(std::max(kGuardBytes * 2, std::size_t{l.free_l1.bytes}),
                                           kGuardByte);
  for (const ChunkLayout::Zone& z : {l.before_l2, l.after_l2, l.after_results, l.free_l1})
    mem.Write(z.at, sentinel.data(), z.bytes);
}

std::vector<std::uint8_t> read_zone(gap8::Memory& mem, const ChunkLayout::Zone& z) {
  std::vector<std::uint8_t> bytes(z.bytes);
  mem.Read(z.at, bytes.data(), z.bytes);
  return bytes;
}

// After the run: the tests' planted overrun stored, then every guard zone checked. In L1 the
// records of the last pair run are the last allocation, or the fast tables are: the zone starts
// at the allocator's final mark, read from `l1_next_addr`.
void check_guards(gap8::Memory& mem, const ChunkLayout& l, const RunOptions& options,
                  std::uint32_t l1_next_addr) {
  const std::uint8_t planted = 0;
  if (options.plant_past_l2_records)
    mem.Write(l.l2_records_end + options.plant_past_l2_records - 1, &planted, 1);
  if (options.plant_past_l1_records)
    mem.Write(l.l1_records_end + options.plant_past_l1_records - 1, &planted, 1);
  const std::uint32_t records = l.pois * static_cast<std::uint32_t>(l.pairs);
  check_guard_before(read_zone(mem, l.before_l2), "gap8 model (L2 records)");
  check_guard_after(read_zone(mem, l.after_l2), records, "gap8 model (L2 records)");
  check_guard_after(read_zone(mem, l.after_results), l.pairs, "gap8 model (L2 results, per pair)");
  std::uint32_t l1_next = 0;
  mem.Read(l1_next_addr, &l1_next, sizeof l1_next);
  if (l1_next < l.l1_records_end || l1_next > l.l1_heap_end)
    throw BackendError("gap8 model: the kernel's L1 allocations end at " + std::to_string(l1_next) +
                       ", outside its records' end and the heap's");
  check_guard_after(read_zone(mem, {l1_next, l.l1_heap_end - l1_next}), l.pois,
                    l1_next == l.l1_records_end
                        ? "gap8 model (L1 records)"
                        : "gap8 model (L1, past the tables after the records)");
}

// The records into `out`, the kernel's results per pair appended to `stats`.
void read_outputs(gap8::Memory& mem, const ChunkLayout& l, std::span<PoiRecord> out,
                  BatchStats& stats) {
  mem.Read(l.block.records_l2, out.data(), static_cast<std::uint32_t>(l.rec_bytes * l.pairs));
  const std::size_t first = stats.pairs.size();
  stats.pairs.resize(first + l.pairs);
  mem.Read(l.block.results_l2, &stats.pairs[first],
           static_cast<std::uint32_t>(l.pairs * sizeof(pxflow_gap8_result)));
}

void add_core_totals(gap8::Cluster& cluster, int cores, BatchStats& stats) {
  for (int c = 0; c < cores; ++c) {
    const gap8::EventTotals t = cluster.core(c).Totals();
    for (std::size_t e = 0; e < t.size(); ++e) stats.cores[c][e] += t[e];
  }
}

}  // namespace

ChunkLayout FlowRunner::chunk_layout(const Params& p, std::size_t n,
                                     const RunOptions& options) const {
  ChunkLayout l;
  l.pairs = n;
  l.frame = static_cast<std::uint32_t>(p.width * p.height);
  l.pois = static_cast<std::uint32_t>(poi_count(p));
  l.rec_bytes = l.pois * static_cast<std::uint32_t>(sizeof(PoiRecord));
  pxflow_gap8_params& block = l.block;
  block.magic = PXFLOW_GAP8_MAGIC;
  block.spec = spec_params(p);
  block.pairs = static_cast<std::uint32_t>(n);
  block.cores = options.cores;
  block.split = options.chunked ? PXFLOW_GAP8_SPLIT_CHUNKED : PXFLOW_GAP8_SPLIT_ROUND_ROBIN;
  block.frames_l2 = io_base_;
  block.records_l2 = io_base_ + align_up(std::uint64_t(2) * l.frame * n) + kGuardBytes;
  block.results_l2 = block.records_l2 + align_up(std::uint64_t(l.rec_bytes) * n) + kGuardBytes;
  const std::uint32_t results_end =
      block.results_l2 + static_cast<std::uint32_t>(n * sizeof(pxflow_gap8_result));
  l.l1_records_end =
      l1_heap_start_ + align_up(pxflow_gap8_l1_bytes(p.width, p.height, l.pois, planes_));
  l.l2_records_end = block.records_l2 + l.rec_bytes * static_cast<std::uint32_t>(n);
  const std::uint32_t frames_end = io_base_ + 2 * l.frame * static_cast<std::uint32_t>(n);
  l.before_l2 = {frames_end, block.records_l2 - frames_end};
  l.after_l2 = {l.l2_records_end, block.results_l2 - l.l2_records_end};
  l.after_results = {results_end, kGuardBytes};
  l.l1_heap_end = l1_heap_start_ + l1_heap_bytes_;
  l.free_l1 = {l.l1_records_end, l.l1_heap_end - l.l1_records_end};
  return l;
}

void FlowRunner::run_chunk(std::span<const FramePair> pairs, const Params& p,
                           std::span<PoiRecord> out, const RunOptions& options,
                           BatchStats& stats) const {
  const ChunkLayout l = chunk_layout(p, pairs.size(), options);
  gap8::ClusterConfig config;
  config.cores = options.cores;
  config.contention = options.contention;
  config.putc = [](char) {};
  gap8::Cluster cluster(config);
  gap8::Memory& mem = cluster.memory();
  mem.Write(GAP8_L2_BASE, l2_image_.data(), static_cast<std::uint32_t>(l2_image_.size()));
  mem.Write(params_addr_, &l.block, sizeof l.block);
  write_frames(mem, l, pairs, p);
  fill_guards(mem, l);
  cluster.Start(entry_);
  const gap8::RunResult result = cluster.Run();
  if (result.fault) throw BackendError("gap8: kernel faulted: " + result.fault->Message());
  if (result.exit_code != 0)
    throw BackendError("gap8: kernel exited with status " + std::to_string(result.exit_code));
  check_guards(mem, l, options, l1_next_addr_);
  read_outputs(mem, l, out, stats);
  stats.cycles += result.cycles;
  add_core_totals(cluster, options.cores, stats);
}

}  // namespace pxflow::gap8_host
