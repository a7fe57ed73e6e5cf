// The CPU kernels: one per instruction set of isas.def, each in its own file <name>.cpp compiled
// with that row's flags only (swar.cpp is portable C++). An ISA file
// provides only the two hot steps of SPEC §3 (the integer search and the eight half-pixel SADs)
// behind plain function pointers; the per-POI walk, the feature test and the record writing are
// portable code in poi_loop.cpp, shared by every ISA.
//
// Why function pointers and raw pointers only: an ISA file compiled with -mavx512bw that
// instantiated a shared inline or template function (std::vector, std::span, ...) could hand the
// linker an AVX-512 copy of it for the whole program. ISA files therefore keep everything they
// define internal (anonymous namespaces) and export only the IsaKernel table below.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>

#include "frame.hpp"
#include "isa_arch.hpp"
#include "params.hpp"
#include "record.hpp"

namespace pxflow::cpu {

struct BlockMatch {
  int dx = 0;  // -S..S
  int dy = 0;
  std::uint32_t sad = 0;
};

// The search window of one POI at (x, y) with radius S: the pixels of `next` from column x-S-1
// and row y-S-1, 2S+10 rows of 2S+10 columns (the integer search uses the inner 2S+8, the
// half-pixel step one more on each side). `data` points at its top-left pixel; a kernel may read
// up to `row_bytes(S)` bytes from the start of each of its rows and no row outside it. When
// those bytes would run past the right edge of the frame, the caller copies the window into a
// zero-padded buffer first.
// (16 bytes, so that it travels in registers: a larger struct goes through the stack.)
struct Window {
  const std::uint8_t* data = nullptr;
  std::ptrdiff_t stride = 0;
};

// The POI's 8x8 block in `prev`: top-left pixel and row stride.
struct Block {
  const std::uint8_t* data = nullptr;
  std::ptrdiff_t stride = 0;
};

struct IsaKernel {
  const char* name;  // its row's name in isas.def
  // Bytes from the start of a window row this kernel may read, for radius S (>= 2S+10).
  int (*row_bytes)(int radius);
  // SPEC §3 step 1 for `q` = prev(i+2, j+2), or null for the portable SWAR form (which
  // counts its 6 operations).
  std::uint16_t (*feature)(const std::uint8_t* q, std::ptrdiff_t stride);
  // SPEC §3 step 2: the first candidate in raster order (dy outer, dx inner) with the smallest
  // SAD. `counts` is non-null only for kernels that count their 4-byte operations.
  BlockMatch (*search)(Block prev, Window next, int radius, OpCounts* counts);
  // SPEC §3 step 3: sub[k] for k = 0..7. `around` points at P(-1, -1) of the matched block
  // (window row dy+S, column dx+S); reads stay within P(-1..8, -1..8). Null where the ISA has
  // half_pixel_vote instead.
  void (*half_pixel)(Block prev, const std::uint8_t* around, std::ptrdiff_t stride,
                     std::uint32_t sub[8], OpCounts* counts);
  bool counts_ops;  // true: the kernel charges its USAD8/USADA8/UHADD8 work (the SWAR model)
  // Optional: step 2 for two POIs of one grid row at once (out[0] for a, out[1] for b, each
  // what `search` gives), for radius <= pair_max_radius and windows read in place; null where
  // an ISA has none.
  void (*search_pair)(Block prev_a, Window next_a, Block prev_b, Window next_b, int radius,
                      BlockMatch out[2]) = nullptr;
  int pair_max_radius = 0;
  // Optional: step 3 with its vote, used instead of half_pixel where given: writes sub[0..7]
  // (the record's field) and returns the direction 0..8 that ref::select_half_pixel would choose
  // against the integer match's `sad` (the first k = 0..7 with the smallest sub[k], where that
  // is strictly below `sad`, else 8), so the driver needs no branch on the SADs.
  int (*half_pixel_vote)(Block prev, const std::uint8_t* around, std::ptrdiff_t stride,
                         std::uint32_t sad, std::uint16_t sub[8]) = nullptr;
};

// The accessor of every row of isas.def compiled for this architecture, cpu::<name>_kernel(),
// defined in <name>.cpp. Call one only for an ISA this CPU has (isa_table.hpp's cpu_has).
#define PXFLOW_CPU_ISA(name, arch, flags, ceiling, needs, test) \
  PXFLOW_CPU_ISA_IF_##arch(const IsaKernel& name##_kernel();, )
#include "isas.def"
#undef PXFLOW_CPU_ISA

// One frame pair through kernel `k`: writes all poi_count(p) records of `out` (every byte,
// SPEC §4). `p` must be valid and match the frames. Counts are added when k counts them.
void run_flow(const IsaKernel& k, const FramePair& pair, const Params& p, std::span<PoiRecord> out,
              OpCounts& counts);

// The POIs of grid rows first_row .. end_row-1 only (`out` still holds the whole pair's
// records; only those rows' are written): lets the host split one frame over several cores.
void run_flow_rows(const IsaKernel& k, const FramePair& pair, const Params& p, int first_row,
                   int end_row, std::span<PoiRecord> out, OpCounts& counts);

}  // namespace pxflow::cpu
