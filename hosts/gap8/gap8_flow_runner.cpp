#include "gap8_flow_runner.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "errors.hpp"
#include "gap8/cluster.h"
#include "gap8/elf_loader.h"
#include "gap8_kernel_elf.hpp"
#include "grid.hpp"
#include "spec_params.hpp"

namespace pxflow::gap8_host {
namespace {

// The records the kernel writes are PoiRecords (reference/spec_core.cpp asserts the layouts).
static_assert(sizeof(pxflow_gap8_params) == (1 + PXFLOW_PARAM_FIELDS + 6) * 4);

constexpr std::uint32_t kAlign = 8;
std::uint32_t align_up(std::uint64_t v) {
  return static_cast<std::uint32_t>((v + kAlign - 1) & ~std::uint64_t{kAlign - 1});
}

// libelf reads files: the embedded bytes go through a private temporary file, removed at once.
gap8::ElfImage load_embedded(std::span<const std::uint8_t> elf, gap8::Memory& memory) {
  const char* dir = std::getenv("TMPDIR");
  std::string path = std::string(dir && *dir ? dir : "/tmp") + "/pxflow-gap8-XXXXXX";
  const int fd = mkstemp(path.data());
  if (fd < 0) throw BackendError("gap8: cannot create a temporary file for the kernel ELF");
  const bool written = write(fd, elf.data(), elf.size()) == static_cast<ssize_t>(elf.size());
  close(fd);
  try {
    if (!written) throw BackendError("gap8: cannot write the kernel ELF to " + path);
    gap8::ElfImage image = gap8::LoadElf(path, memory);
    unlink(path.c_str());
    return image;
  } catch (const gap8::ElfError& e) {
    unlink(path.c_str());
    throw BackendError(std::string("gap8: ") + e.what());
  } catch (...) {
    unlink(path.c_str());
    throw;
  }
}

std::uint32_t symbol(const gap8::ElfImage& image, const std::string& name) {
  const auto it = image.symbols.find(name);
  if (it == image.symbols.end()) throw BackendError("gap8: kernel ELF has no symbol " + name);
  return it->second;
}

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
  l1_heap_bytes_ = symbol(image, "__l1_heap_end") - symbol(image, "__l1_heap_start");
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
  if (need > l1_heap_bytes_)
    return "does not fit L1: " + what + " need " + std::to_string(need) + " bytes, the L1 heap " +
           "beside 8 core stacks has " + std::to_string(l1_heap_bytes_);
  if (pair_io_bytes(p) > GAP8_L2_BASE + GAP8_L2_SIZE - io_base_) return "does not fit L2";
  return {};
}

std::size_t FlowRunner::pairs_per_chunk(const Params& p) const {
  return (GAP8_L2_BASE + GAP8_L2_SIZE - io_base_) / pair_io_bytes(p);
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

void FlowRunner::run_chunk(std::span<const FramePair> pairs, const Params& p,
                           std::span<PoiRecord> out, const RunOptions& options,
                           BatchStats& stats) const {
  const std::size_t n = pairs.size();
  const std::uint32_t frame = static_cast<std::uint32_t>(p.width * p.height);
  const std::uint32_t pois = static_cast<std::uint32_t>(poi_count(p));
  const std::uint32_t rec_bytes = pois * static_cast<std::uint32_t>(sizeof(PoiRecord));

  pxflow_gap8_params block{};
  block.magic = PXFLOW_GAP8_MAGIC;
  block.spec = spec_params(p);
  block.pairs = static_cast<std::uint32_t>(n);
  block.cores = options.cores;
  block.split = options.chunked ? PXFLOW_GAP8_SPLIT_CHUNKED : PXFLOW_GAP8_SPLIT_ROUND_ROBIN;
  block.frames_l2 = io_base_;
  block.records_l2 = io_base_ + align_up(std::uint64_t(2) * frame * n);
  block.results_l2 = block.records_l2 + align_up(std::uint64_t(rec_bytes) * n);

  gap8::ClusterConfig config;
  config.cores = options.cores;
  config.contention = options.contention;
  config.putc = [](char) {};
  gap8::Cluster cluster(config);
  gap8::Memory& mem = cluster.memory();
  mem.Write(GAP8_L2_BASE, l2_image_.data(), static_cast<std::uint32_t>(l2_image_.size()));
  mem.Write(params_addr_, &block, sizeof block);
  for (std::size_t i = 0; i < n; ++i) {
    for (int which = 0; which < 2; ++which) {
      const FrameView& f = which == 0 ? pairs[i].prev : pairs[i].next;
      std::uint32_t at = block.frames_l2 + static_cast<std::uint32_t>((2 * i + which) * frame);
      for (int y = 0; y < p.height; ++y, at += p.width) mem.Write(at, f.row(y), p.width);
    }
  }
  cluster.Start(entry_);
  const gap8::RunResult result = cluster.Run();
  if (result.fault) throw BackendError("gap8: kernel faulted: " + result.fault->Message());
  if (result.exit_code != 0)
    throw BackendError("gap8: kernel exited with status " + std::to_string(result.exit_code));

  mem.Read(block.records_l2, out.data(), static_cast<std::uint32_t>(rec_bytes * n));
  const std::size_t first = stats.pairs.size();
  stats.pairs.resize(first + n);
  mem.Read(block.results_l2, &stats.pairs[first],
           static_cast<std::uint32_t>(n * sizeof(pxflow_gap8_result)));
  stats.cycles += result.cycles;
  for (int c = 0; c < options.cores; ++c) {
    const gap8::EventTotals t = cluster.core(c).Totals();
    for (std::size_t e = 0; e < t.size(); ++e) stats.cores[c][e] += t[e];
  }
}

}  // namespace pxflow::gap8_host
