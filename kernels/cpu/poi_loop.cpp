// The portable part of every CPU kernel: the walk over the POI grid, the feature test, the search
// window (copied only where a kernel's wide loads would leave the frame) and the record.

#include <cstring>

#include "cpu_kernel.hpp"
#include "grid.hpp"
#include "poi_steps.hpp"
#include "primitives.hpp"
#include "window_guard.hpp"

namespace pxflow::cpu {
namespace {

// Copies n >= 8 bytes in fixed-size chunks (the last one overlapping): a variable-length memcpy
// call per row would cost more than the search of a small window.
void copy_row(std::uint8_t* dst, const std::uint8_t* src, int n) {
  const int chunk = n >= 16 ? 16 : 8;
  int at = 0;
  for (; at + chunk <= n; at += chunk) {
    if (chunk == 16)
      std::memcpy(dst + at, src + at, 16);
    else
      std::memcpy(dst + at, src + at, 8);
  }
  if (at < n) {
    if (chunk == 16)
      std::memcpy(dst + n - 16, src + n - 16, 16);
    else
      std::memcpy(dst + n - 8, src + n - 8, 8);
  }
}

// A zero-padded copy of the window whose top-left pixel is next(x0, y0), for POIs whose kernel
// reads would leave the frame on the right; the guard bytes around it are checked after the copy.
Window copy_window(const FrameView& next, int x0, int y0, WindowGuard& copy) {
  for (int r = 0; r < copy.side(); ++r) copy_row(copy.row(r), next.row(y0 + r) + x0, copy.side());
  copy.check(y0);
  return {copy.row(0), copy.stride()};
}

// SPEC §3 step 1 in the firmware's shape: three USAD8 of vertically adjacent 4-byte rows and
// three of horizontally adjacent 4-byte columns of the central 4x4.
std::uint16_t feature(const FrameView& prev, int i, int j, OpCounts* counts) {
  const std::uint8_t* q = prev.row(j + 2) + i + 2;
  const std::ptrdiff_t s = prev.stride;
  std::uint32_t rows[4], cols[4];
  for (int r = 0; r < 4; ++r) rows[r] = load4(q + r * s);
  for (int c = 0; c < 4; ++c) {
    const std::uint8_t bytes[4] = {q[c], q[s + c], q[2 * s + c], q[3 * s + c]};
    cols[c] = load4(bytes);
  }
  std::uint32_t sum = 0;
  for (int r = 0; r < 3; ++r) sum = usada8(rows[r], rows[r + 1], sum);
  for (int c = 0; c < 3; ++c) sum = usada8(cols[c], cols[c + 1], sum);
  if (counts) counts->sad_ops += 6;
  return static_cast<std::uint16_t>(sum);
}

struct PoiContext {
  const IsaKernel& kernel;
  const FramePair& pair;
  const Params& p;
  int row_bytes;
  OpCounts* counts;
  WindowGuard& copy;
};

// Steps 1 and 2 and the record's fields up to `sad`; the half-pixel step is refine_poi's.
void search_poi(const PoiContext& ctx, int x, int y, PoiRecord& rec) {
  const int S = ctx.p.search_radius;
  rec = PoiRecord{};  // every field a status does not define, and the padding, is 0
  rec.x = static_cast<std::uint16_t>(x);
  rec.y = static_cast<std::uint16_t>(y);
  rec.dir = kDirNone;
  rec.feature = ctx.kernel.feature
                    ? ctx.kernel.feature(ctx.pair.prev.row(y + 2) + x + 2, ctx.pair.prev.stride)
                    : feature(ctx.pair.prev, x, y, ctx.counts);
  if (rec.feature < ctx.p.feature_threshold) {
    rec.status = kDropped;
    return;
  }
  const FrameView& next = ctx.pair.next;
  Window w{next.row(y - S - 1) + (x - S - 1), next.stride};
  if (x - S - 1 + ctx.row_bytes > next.width) w = copy_window(next, x - S - 1, y - S - 1, ctx.copy);
  const Block block{ctx.pair.prev.row(y) + x, ctx.pair.prev.stride};
  const BlockMatch m = ctx.kernel.search(block, w, S, ctx.counts);
  rec.dx = static_cast<std::int8_t>(m.dx);
  rec.dy = static_cast<std::int8_t>(m.dy);
  rec.sad = static_cast<std::uint16_t>(m.sad);
  rec.status = m.sad < static_cast<std::uint32_t>(ctx.p.sad_threshold) ? kAccepted : kRejected;
}

// Step 3 for an accepted POI. It reads P(-1..8, -1..8) only, always inside the frame (SPEC §3),
// so it reads the frame in place even where the search needed a padded copy of the window.
void refine_poi(const PoiContext& ctx, PoiRecord& rec) {
  const FrameView& next = ctx.pair.next;
  const Block block{ctx.pair.prev.row(rec.y) + rec.x, ctx.pair.prev.stride};
  const std::uint8_t* around = next.row(rec.y + rec.dy - 1) + (rec.x + rec.dx - 1);
  std::uint32_t sub[8];
  ctx.kernel.half_pixel(block, around, next.stride, sub, ctx.counts);
  ref::select_half_pixel(rec, ref::Match{rec.dx, rec.dy, rec.sad}, sub);
}

}  // namespace

void run_flow_rows(const IsaKernel& k, const FramePair& pair, const Params& p, int first_row,
                   int end_row, std::span<PoiRecord> out, OpCounts& counts) {
  OpCounts* charged = k.counts_ops ? &counts : nullptr;
  if (charged) counts.counted = true;
  const int row_bytes = k.row_bytes(p.search_radius);
  WindowGuard copy(2 * p.search_radius + 10, row_bytes);
  const PoiContext ctx{k, pair, p, row_bytes, charged, copy};
  const std::vector<int> xs = grid_axis(p.width, p);
  const std::vector<int> ys = grid_axis(p.height, p);
  // A grid row's searches first, then its half-pixel steps: each step's calls are independent
  // of each other, so the core overlaps one POI's search with the next one's instead of waiting
  // for each match before its refinement can start (a quarter of the time at px4flow-64).
  for (int row = first_row; row < end_row; ++row) {
    const std::size_t first = static_cast<std::size_t>(row) * xs.size();
    std::size_t n = first;
    for (int x : xs) search_poi(ctx, x, ys[static_cast<std::size_t>(row)], out[n++]);
    for (n = first; n < first + xs.size(); ++n)
      if (out[n].status == kAccepted) refine_poi(ctx, out[n]);
  }
}

void run_flow(const IsaKernel& k, const FramePair& pair, const Params& p, std::span<PoiRecord> out,
              OpCounts& counts) {
  const auto rows = static_cast<int>(grid_axis(p.height, p).size());
  run_flow_rows(k, pair, p, 0, rows, out, counts);
}

}  // namespace pxflow::cpu
