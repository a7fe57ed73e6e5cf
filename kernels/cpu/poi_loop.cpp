// The portable part of every CPU kernel: the walk over the POI grid, the feature test, the search
// window (copied only where a kernel's wide loads would leave the frame) and the record.

#include <algorithm>
#include <cstring>
#include <optional>

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
// The buffer is made at a call's first copy: most kernels never need one (avx512bw's masked
// loads, the 8-byte loads of sse2, swar and neon), and making it costs more than the walk of
// a small frame.
Window copy_window(const FrameView& next, int x0, int y0, int side, int row_bytes,
                   std::optional<WindowGuard>& guard) {
  if (!guard) guard.emplace(side, row_bytes);
  WindowGuard& copy = *guard;
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
  std::optional<WindowGuard>& copy;
};

// Step 1 and the record's fields up to `feature`; false when the POI is dropped (then complete).
// Inlined, like search_started: as calls they made every ISA's walk some 6 % slower (avx2, S = 4).
[[gnu::always_inline]] inline bool start_poi(const PoiContext& ctx, int x, int y, PoiRecord& rec) {
  rec = PoiRecord{};  // every field a status does not define, and the padding, is 0
  rec.x = static_cast<std::uint16_t>(x);
  rec.y = static_cast<std::uint16_t>(y);
  rec.dir = kDirNone;
  rec.feature = ctx.kernel.feature
                    ? ctx.kernel.feature(ctx.pair.prev.row(y + 2) + x + 2, ctx.pair.prev.stride)
                    : feature(ctx.pair.prev, x, y, ctx.counts);
  if (rec.feature < ctx.p.feature_threshold) {
    rec.status = kDropped;
    return false;
  }
  return true;
}

// The POI's window read in place: its kernel's loads stay inside the frame's rows.
bool window_in_place(const PoiContext& ctx, int x) {
  return x - ctx.p.search_radius - 1 + ctx.row_bytes <= ctx.pair.next.width;
}

Window frame_window(const PoiContext& ctx, int x, int y) {
  const int S = ctx.p.search_radius;
  return {ctx.pair.next.row(y - S - 1) + (x - S - 1), ctx.pair.next.stride};
}

Block block_of(const PoiContext& ctx, const PoiRecord& rec) {
  return {ctx.pair.prev.row(rec.y) + rec.x, ctx.pair.prev.stride};
}

// Step 2's fields of the record.
void finish_search(const PoiContext& ctx, const BlockMatch& m, PoiRecord& rec) {
  rec.dx = static_cast<std::int8_t>(m.dx);
  rec.dy = static_cast<std::int8_t>(m.dy);
  rec.sad = static_cast<std::uint16_t>(m.sad);
  rec.status = m.sad < static_cast<std::uint32_t>(ctx.p.sad_threshold) ? kAccepted : kRejected;
}

// Step 2 for a POI that passed step 1.
[[gnu::always_inline]] inline void search_started(const PoiContext& ctx, PoiRecord& rec) {
  const int S = ctx.p.search_radius;
  Window w = frame_window(ctx, rec.x, rec.y);
  if (!window_in_place(ctx, rec.x))
    w = copy_window(ctx.pair.next, rec.x - S - 1, rec.y - S - 1, 2 * S + 10, ctx.row_bytes,
                    ctx.copy);
  finish_search(ctx, ctx.kernel.search(block_of(ctx, rec), w, S, ctx.counts), rec);
}

// Steps 1 and 2 and the record's fields up to `sad`; the half-pixel step is refine_poi's.
void search_poi(const PoiContext& ctx, int x, int y, PoiRecord& rec) {
  if (start_poi(ctx, x, y, rec)) search_started(ctx, rec);
}

// Step 2 for two POIs that passed step 1, with windows in place, by the kernel's search_pair.
void search_two(const PoiContext& ctx, PoiRecord& a, PoiRecord& b) {
  BlockMatch m[2];
  ctx.kernel.search_pair(block_of(ctx, a), frame_window(ctx, a.x, a.y), block_of(ctx, b),
                         frame_window(ctx, b.x, b.y), ctx.p.search_radius, m);
  finish_search(ctx, m[0], a);
  finish_search(ctx, m[1], b);
}

// Steps 1 and 2 for grid row `first`.. of `count` POIs at y, two at a time where the kernel can:
// a POI that passed step 1 waits for the next one that does.
class RowSearch {
 public:
  RowSearch(const PoiContext& ctx, std::span<PoiRecord> out)
      : ctx_(ctx),
        out_(out),
        pairs_(ctx.kernel.search_pair && ctx.p.search_radius <= ctx.kernel.pair_max_radius) {}

  void poi(std::size_t n, int x, int y) {
    if (!pairs_) return search_poi(ctx_, x, y, out_[n]);
    if (!start_poi(ctx_, x, y, out_[n])) return;
    if (!window_in_place(ctx_, x)) return search_started(ctx_, out_[n]);
    if (!waiting_) {
      waiting_ = &out_[n];
      return;
    }
    search_two(ctx_, *waiting_, out_[n]);
    waiting_ = nullptr;
  }
  void end_row() {
    if (waiting_) search_started(ctx_, *waiting_);
    waiting_ = nullptr;
  }

 private:
  const PoiContext& ctx_;
  std::span<PoiRecord> out_;
  bool pairs_;
  PoiRecord* waiting_ = nullptr;
};

// Step 3 for an accepted POI. It reads P(-1..8, -1..8) only, always inside the frame (SPEC §3),
// so it reads the frame in place even where the search needed a padded copy of the window.
void refine_poi(const PoiContext& ctx, PoiRecord& rec) {
  const FrameView& next = ctx.pair.next;
  const Block block{ctx.pair.prev.row(rec.y) + rec.x, ctx.pair.prev.stride};
  const std::uint8_t* around = next.row(rec.y + rec.dy - 1) + (rec.x + rec.dx - 1);
  if (ctx.kernel.half_pixel_vote) {  // dir only: hx and hy after the row (run_flow_rows)
    rec.dir = static_cast<std::uint8_t>(
        ctx.kernel.half_pixel_vote(block, around, next.stride, rec.sad, rec.sub));
    return;
  }
  std::uint32_t sub[8];
  ctx.kernel.half_pixel(block, around, next.stride, sub, ctx.counts);
  ref::select_half_pixel(rec, ref::Match{rec.dx, rec.dy, rec.sad}, sub);
}

// The frame rows a grid row reads that the grid row above it did not: of `next`, its windows'
// rows down to y + S + 8 (from y - S - 1 for the first), of `prev`, its blocks' rows y .. y + 7,
// each across the grid's columns. Asking for them (a hint: no fault, no effect on any result)
// one grid row ahead, a slice per POI, lets the memory system fetch them while the core
// computes: a call's frames usually come from memory (the caller's other work evicted them),
// and in turn a window's 2S + 10 lines would each be waited for.
class RowPrefetch {
 public:
  RowPrefetch(const FramePair& pair, const GridAxis& xs, int S)
      : pair_(pair), S_(S), x0_(xs.first - S - 1), n_((xs.count - 1) * xs.step + 2 * S + 10) {}

  // Rows of grid row y (y_above: the grid row before it, or none when y is the first).
  void plan(int y, int y_above, bool first) {
    next_from_ = first ? y - S_ - 1 : std::max(y_above + S_ + 9, y - S_ - 1);
    next_end_ = y + S_ + 9;
    prev_from_ = y;
    rows_ = (next_end_ - next_from_) + 8;
  }
  // Slice `part` of `parts` of the planned rows.
  [[gnu::always_inline]] void fetch(int part, int parts) const {
    for (int k = part * rows_ / parts; k < (part + 1) * rows_ / parts; ++k) {
      const int in_next = next_end_ - next_from_;
      const std::uint8_t* row = k < in_next
                                    ? pair_.next.row(next_from_ + k) + x0_
                                    : pair_.prev.row(prev_from_ + k - in_next) + x0_ + S_ + 1;
      const int n = k < in_next ? n_ : n_ - 2 * S_ - 2;
      // A prefetch is a builtin GCC's IPA would let it drop from a helper it deems pure: it is
      // written here, inlined, where it stays.
      for (int at = 0; at < n + 63; at += 64) __builtin_prefetch(row + std::min(at, n - 1));
    }
  }

 private:
  const FramePair& pair_;
  int S_, x0_, n_;
  int next_from_ = 0, next_end_ = 0, prev_from_ = 0, rows_ = 0;
};

// A pair of at most this many bytes takes no hints (see run_flow_rows).
constexpr std::ptrdiff_t kSmallPairBytes = 24 * 1024;

// The pages of a large pair are looked up once, at the start of a call, each by a load of one
// byte (touch_pages): a call's pair usually comes after other work (LK and DIS in pxflow
// accuracy), its translations gone, and the searches would otherwise meet the page walks one at a
// time. pxflow_accuracy_probe (docs/accuracy.md), 768x576 S=7 B=32, 216 pages: 147 -> 135 us a
// frame; 320x240 (38 pages): no change, and 3 % slower for tree.avi. Hence only pairs whose rows
// span more pages than the first-level data TLB has 4 KB entries (96 on Golden Cove).
constexpr std::uintptr_t kPage = 4096;
constexpr std::uintptr_t kTouchAbovePages = 96;

// How many 4 KB pages rows y0..y1 of f span, the gaps between rows included. The rows lie in
// the frame: the grid keeps every window inside it (SPEC §2).
std::uintptr_t pages_spanned(const FrameView& f, int y0, int y1) {
  const auto from = reinterpret_cast<std::uintptr_t>(f.row(y0));
  const auto end = reinterpret_cast<std::uintptr_t>(f.row(y1) + f.width);
  return (end - 1) / kPage - from / kPage + 1;
}

// One load of the first byte of each page that rows y0..y1 of f reach, in address order, where
// that byte is a pixel: a page that starts between two rows (those bytes may belong to someone
// else) is left to the searches. Every load lies in [base, end). Touching the rows' own first and
// last pixels instead, row by row, gained nothing.
void touch_pages(const FrameView& f, int y0, int y1) {
  const auto base = reinterpret_cast<std::uintptr_t>(f.row(y0));
  const auto end = reinterpret_cast<std::uintptr_t>(f.row(y1) + f.width);
  for (std::uintptr_t at = base; at < end; at = (at | (kPage - 1)) + 1) {
    // x: at's column in its row; the bytes between two rows are columns W .. stride - 1.
    const auto x = static_cast<std::ptrdiff_t>(at - base) % f.stride;
    if (x < f.width) (void)*reinterpret_cast<const volatile std::uint8_t*>(at);
  }
}

// The rows grid rows y0..y1 read: of next, their windows'; of prev, their blocks'.
void touch_pages_if_many(const FramePair& pair, int S, int y0, int y1) {
  const std::uintptr_t pages =
      pages_spanned(pair.next, y0 - S - 1, y1 + S + 8) + pages_spanned(pair.prev, y0, y1 + 7);
  if (pages <= kTouchAbovePages) return;
  touch_pages(pair.next, y0 - S - 1, y1 + S + 8);
  touch_pages(pair.prev, y0, y1 + 7);
}

}  // namespace

void run_flow_rows(const IsaKernel& k, const FramePair& pair, const Params& p, int first_row,
                   int end_row, std::span<PoiRecord> out, OpCounts& counts) {
  OpCounts* charged = k.counts_ops ? &counts : nullptr;
  if (charged) counts.counted = true;
  const int row_bytes = k.row_bytes(p.search_radius);
  WindowGuard::require_row_bytes(2 * p.search_radius + 10, row_bytes);
  std::optional<WindowGuard> copy;
  const PoiContext ctx{k, pair, p, row_bytes, charged, copy};
  const GridAxis xs = grid_axis_triple(p.width, p);
  const GridAxis ys = grid_axis_triple(p.height, p);
  const auto per_row = static_cast<std::size_t>(xs.count);
  RowPrefetch ahead(pair, xs, p.search_radius);
  RowSearch search(ctx, out);
  // A pair that fits in half the L1 cache (64x64: 4 KB a frame) gained nothing from memory
  // and lost 6-7 % from L2 (pxflow bench, px4flow-64, batch 256): the hints are for large frames.
  const bool prefetch = 2 * pair.next.stride * p.height > kSmallPairBytes;
  if (prefetch && first_row < end_row) {
    ahead.plan(ys.first + first_row * ys.step, 0, true);
    ahead.fetch(0, 1);
    touch_pages_if_many(pair, p.search_radius, ys.first + first_row * ys.step,
                        ys.first + (end_row - 1) * ys.step);
  }
  // A grid row's searches first, then its half-pixel steps: each step's calls are independent
  // of each other, so the core overlaps one POI's search with the next one's instead of waiting
  // for each match before its refinement can start (a quarter of the time at px4flow-64).
  for (int row = first_row; row < end_row; ++row) {
    const int y = ys.first + row * ys.step;
    const std::size_t first = static_cast<std::size_t>(row) * per_row;
    const bool more = prefetch && row + 1 < end_row;
    if (more) ahead.plan(y + ys.step, y, false);
    for (int c = 0; c < xs.count; ++c) {
      if (more) ahead.fetch(c, xs.count);
      search.poi(first + static_cast<std::size_t>(c), xs.first + c * xs.step, y);
    }
    search.end_row();
    for (std::size_t n = first; n < first + per_row; ++n)
      if (out[n].status == kAccepted) refine_poi(ctx, out[n]);
    // The half-pixel offsets of half_pixel_vote's directions, after the whole row's steps: each
    // step is a long chain of latencies, and a write after each call that waits for its result
    // keeps the next call's work out of the core's window.
    if (ctx.kernel.half_pixel_vote)
      for (std::size_t n = first; n < first + per_row; ++n)
        if (out[n].status == kAccepted)
          ref::record_direction(out[n], ref::Match{out[n].dx, out[n].dy, out[n].sad}, out[n].dir);
  }
}

void run_flow(const IsaKernel& k, const FramePair& pair, const Params& p, std::span<PoiRecord> out,
              OpCounts& counts) {
  run_flow_rows(k, pair, p, 0, grid_axis_triple(p.height, p).count, out, counts);
}

}  // namespace pxflow::cpu
