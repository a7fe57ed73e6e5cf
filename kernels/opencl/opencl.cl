// The PX4FLOW per-POI kernel (SPEC sec. 3) in OpenCL C 1.2, the opencl family's device code.
//
// Memory layout shared with the host (hosts/opencl/opencl_launch.cpp):
//   frames:  for each pair of the launch, prev then next, each width*height bytes, rows packed.
//   records: for each pair, one PoiRecord per grid POI in grid order, written as 8 little-endian
//            uint words with exactly the byte layout of reference/record.hpp.
//
// Two work decompositions share the per-POI helpers below, each a registry row
// (hosts/opencl/opencl_rows.cpp; docs/opencl.md compares them and says why both ship):
//   flow_group_per_poi (row opencl-group): one work-group per POI; the 8x8 prev block and the
//                       search window of next are staged in local memory, work-items split
//                       the candidates.
//   flow_item_per_poi (row opencl-item): one work-item per POI, everything from global memory
//                       (from S = 5 on, the window copied into private memory: best_key_lanes).
//
// Floor averaging everywhere: hadd(), never rhadd() (rhadd rounds up, SPEC sec. 7).

// SPEC's codes and step table are the spec core's (spec/include/pxflow_spec/record.h); this file
// is compiled at run time from its text, so it spells them, and ctest spec_copies checks them.
// Half-pixel step (sx, sy) of direction k (SPEC sec. 3 table); k = 8 is the integer match.
__constant int kStepX[9] = {1, 1, 0, -1, -1, -1, 0, 1, 0};
__constant int kStepY[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};

// PoiRecord::dir and status values (the spec core's PXFLOW_DIR_NONE, PXFLOW_STATUS_*).
#define DIR_NONE 8u
#define STATUS_DROPPED 0u
#define STATUS_REJECTED 1u
#define STATUS_ACCEPTED 2u

// Candidate keys pack (SAD, raster index) so that one unsigned minimum gives the lowest SAD
// and, among equal SADs, the first candidate in raster order (strictly-smaller-replaces).
// SAD <= 16320 < 2^14 and the raster index < 63*63 < 2^12 leave the top 6 bits clear.
#define KEY_INDEX_BITS 12
#define KEY_INDEX_MASK ((1u << KEY_INDEX_BITS) - 1u)

// Where a POI is and where its pixels live; the same for both decompositions.
typedef struct {
  int x, y;    // top-left corner of the 8x8 block in prev
  int radius;  // S
} Poi;

inline uint lane_sum(ushort8 v) {
  uint4 s = convert_uint4(v.lo) + convert_uint4(v.hi);
  s.xy += s.zw;
  return s.x + s.y;
}

// |a - b| per lane. Not abs_diff(): PoCL 3.1 lowers abs_diff on uchar8 to scalar code, and the
// search ran 7x slower (docs/measurements/opencl-kernel.md); max - min cannot wrap: plain SIMD.
inline ushort8 row_sad(uchar8 a, uchar8 b) { return convert_ushort8(max(a, b) - min(a, b)); }

// SPEC sec. 3 step 1: 24 absolute differences over the central 4x4 of the block.
inline uint feature_of(const uchar8 block[8]) {
  uint sum = 0;
  for (int r = 0; r < 3; ++r) {  // vertical neighbours
    const uchar4 a = block[2 + r].s2345, b = block[3 + r].s2345;
    const uchar4 d = max(a, b) - min(a, b);
    sum += (uint)d.s0 + d.s1 + d.s2 + d.s3;
  }
  for (int r = 0; r < 4; ++r) {  // horizontal neighbours
    const uchar3 a = block[2 + r].s234, b = block[2 + r].s345;
    const uchar3 d = max(a, b) - min(a, b);
    sum += (uint)d.s0 + d.s1 + d.s2;
  }
  return sum;
}

// The eight direction values of block row r, given P rows r-1, r, r+1 at columns -1, 0, +1
// (p[v][o] = P(o - 1 + c, r - 1 + v) for c = 0..7). Diagonals average two HORIZONTAL
// averages, each floored (SPEC sec. 3).
inline void direction_row(const uchar8 p[3][3], uchar8 value[8]) {
  uchar8 h_right[3], h_left[3];  // h(c, r-1+v) and h(c-1, r-1+v)
  for (int v = 0; v < 3; ++v) {
    h_right[v] = hadd(p[v][1], p[v][2]);
    h_left[v] = hadd(p[v][0], p[v][1]);
  }
  value[0] = h_right[1];
  value[1] = hadd(h_right[1], h_right[2]);
  value[2] = hadd(p[1][1], p[2][1]);
  value[3] = hadd(h_left[1], h_left[2]);
  value[4] = h_left[1];
  value[5] = hadd(h_left[0], h_left[1]);
  value[6] = hadd(p[0][1], p[1][1]);
  value[7] = hadd(h_right[0], h_right[1]);
}

// The address-space-specific helpers: OpenCL C 1.2 has no generic address space, so the same
// two functions are stamped out for __local (work-group decomposition) and __global.
#define DEFINE_WINDOW_HELPERS(SPACE)                                                           \
  /* 8x8 SAD of the block against the 8x8 of `w` (row stride `stride`). */                     \
  inline uint block_sad_##SPACE(const uchar8 block[8], SPACE const uchar* w, int stride) {     \
    ushort8 acc = row_sad(block[0], vload8(0, w));                                             \
    _Pragma("unroll") for (int r = 1; r < 8; ++r) acc +=                                       \
        row_sad(block[r], vload8(0, w + r * stride));                                          \
    return lane_sum(acc);                                                                      \
  }                                                                                            \
  /* The eight half-pixel SADs around the match whose top-left pixel P(0, 0) is at `m`. */     \
  inline void half_pixel_sads_##SPACE(const uchar8 block[8], SPACE const uchar* m, int stride, \
                                      uint sub[8]) {                                           \
    ushort8 acc[8];                                                                            \
    for (int k = 0; k < 8; ++k) acc[k] = (ushort8)(0);                                         \
    for (int r = 0; r < 8; ++r) {                                                              \
      uchar8 p[3][3], value[8];                                                                \
      for (int v = 0; v < 3; ++v)                                                              \
        for (int o = 0; o < 3; ++o) p[v][o] = vload8(0, m + (r - 1 + v) * stride + o - 1);     \
      direction_row(p, value);                                                                 \
      for (int k = 0; k < 8; ++k) acc[k] += row_sad(block[r], value[k]);                       \
    }                                                                                          \
    for (int k = 0; k < 8; ++k) sub[k] = lane_sum(acc[k]);                                     \
  }

DEFINE_WINDOW_HELPERS(__local)
DEFINE_WINDOW_HELPERS(__global)

// SPEC sec. 3 step 3's vote: from (sad, dir 8), k = 0..7 replaces only on strictly smaller.
inline uint vote(uint sad, const uint sub[8]) {
  uint best = sad, dir = DIR_NONE;
  for (uint k = 0; k < 8; ++k) {
    if (sub[k] < best) {
      best = sub[k];
      dir = k;
    }
  }
  return dir;
}

// Writes one record as 8 words (layout: reference/record.hpp). Fields a status does not
// define arrive here as 0, and the padding bytes are never set.
inline void store_record(__global uint* out, Poi poi, uint status, uint feature, int dx, int dy,
                         uint sad, uint dir, const uint sub[8]) {
  const int hx = status == STATUS_ACCEPTED ? 2 * dx + kStepX[dir] : 0;
  const int hy = status == STATUS_ACCEPTED ? 2 * dy + kStepY[dir] : 0;
  uint8 w;
  w.s0 = (uint)poi.x | ((uint)poi.y << 16);
  w.s1 = status | (feature << 16);
  w.s2 = ((uint)dx & 0xFFu) | (((uint)dy & 0xFFu) << 8) | (sad << 16);
  w.s3 = dir | (sub[0] << 16);
  w.s4 = sub[1] | (sub[2] << 16);
  w.s5 = sub[3] | (sub[4] << 16);
  w.s6 = sub[5] | (sub[6] << 16);
  w.s7 = sub[7] | (((uint)hx & 0xFFu) << 16) | (((uint)hy & 0xFFu) << 24);
  vstore8(w, 0, out);
}

inline void store_dropped(__global uint* out, Poi poi, uint feature) {
  const uint zero[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  store_record(out, poi, STATUS_DROPPED, feature, 0, 0, 0, DIR_NONE, zero);
}

// The grid POI `index` of a pair (SPEC sec. 2: y outer, x inner).
inline Poi grid_poi(uint index, int radius, int4 grid_x, int4 grid_y) {
  Poi poi;
  poi.x = grid_x.s0 + (int)(index % (uint)grid_x.s2) * grid_x.s1;
  poi.y = grid_y.s0 + (int)(index / (uint)grid_x.s2) * grid_y.s1;
  poi.radius = radius;
  return poi;
}

// --- flow_group_per_poi ------------------------------------------------------------------

// Copies the search window of next, rows y-S-1 .. y+S+8 and the same columns, into `win`, one
// row per async copy: every work-item takes part, and a GPU coalesces each row's reads.
inline void stage_window(__global const uchar* next, int width, Poi poi, __local uchar* win) {
  const int side = 2 * poi.radius + 10;
  __global const uchar* src = next + (poi.y - poi.radius - 1) * width + poi.x - poi.radius - 1;
  event_t copied = 0;
  for (int row = 0; row < side; ++row)
    copied = async_work_group_copy(win + row * side, src + row * width, side, copied);
  wait_group_events(1, &copied);
}

// Each work-item keeps the minimum key over the candidates it owns (lid, lid + size, ...).
inline uint local_best_key(const uchar8 block[8], __local const uchar* win, int radius) {
  const int span = 2 * radius + 1, side = span + 9;
  uint best = 0xFFFFFFFFu;
  for (int c = get_local_id(0); c < span * span; c += get_local_size(0)) {
    const int dy = c / span, dx = c - dy * span;  // offsets from -S, -S
    const uint sad = block_sad___local(block, win + (dy + 1) * side + dx + 1, side);
    best = min(best, (sad << KEY_INDEX_BITS) | (uint)c);
  }
  return best;
}

// One work-group per POI. Local memory: `win` holds (2S+10)^2 bytes, `keys` one uint per
// work-item. Launched with exactly pairs * POIs-per-pair work-groups.
__kernel void flow_group_per_poi(__global const uchar* frames, __global uint* records, int width,
                                 int height, int radius, uint feature_threshold, uint sad_threshold,
                                 int4 grid_x, int4 grid_y, __local uchar* win, __local uint* keys) {
  const uint group = get_group_id(0), lid = get_local_id(0);
  const uint pois = (uint)(grid_x.s2 * grid_y.s2);
  const size_t plane = (size_t)width * (size_t)height;
  __global const uchar* prev = frames + (size_t)(group / pois) * 2 * plane;
  const Poi poi = grid_poi(group % pois, radius, grid_x, grid_y);
  __global uint* out = records + (size_t)group * 8;

  stage_window(prev + plane, width, poi, win);  // complete in every work-item on return
  uchar8 block[8];
  for (int r = 0; r < 8; ++r) block[r] = vload8(0, prev + (poi.y + r) * width + poi.x);

  // The feature test is uniform across the group, so the early exit keeps barriers legal.
  const uint feature = feature_of(block);
  if (feature < feature_threshold) {
    if (lid == 0) store_dropped(out, poi, feature);
    return;
  }
  keys[lid] = local_best_key(block, win, radius);
  barrier(CLK_LOCAL_MEM_FENCE);
  if (lid != 0) return;

  uint best = keys[0];
  for (uint t = 1; t < get_local_size(0); ++t) best = min(best, keys[t]);
  const int span = 2 * radius + 1, side = span + 9;
  const uint index = best & KEY_INDEX_MASK, sad = best >> KEY_INDEX_BITS;
  const int bx = (int)(index % (uint)span), by = (int)(index / (uint)span);  // from -S, -S
  uint sub[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  uint status = STATUS_REJECTED, dir = DIR_NONE;
  if (sad < sad_threshold) {
    half_pixel_sads___local(block, win + (by + 1) * side + bx + 1, side, sub);
    status = STATUS_ACCEPTED;
    dir = vote(sad, sub);
  }
  store_record(out, poi, status, feature, bx - radius, by - radius, sad, dir, sub);
}

// --- flow_item_per_poi -------------------------------------------------------------------

// Four vertically adjacent candidates (dx, dy) .. (dx, dy+3) at once, `w` at the top-left pixel
// of (dx, dy). u[j] pairs next rows j and j+1 in one uchar16, so against (block row r, block row
// r) u[r] gives row r of (dx, dy) in lanes 0-7 and of (dx, dy+1) in lanes 8-15, and u[r+2] the
// same for (dx, dy+2) and (dx, dy+3): eleven row loads serve 32 row SADs, each 16-byte operation
// does two candidates' rows, and LLVM keeps it all in registers (docs/opencl.md, "Work
// decomposition" and "Why OpenCL on PoCL is a fraction of native").
// always_inline: PoCL's LLVM otherwise calls it with the block spilled to the stack (measured).
__attribute__((always_inline)) inline uint4 quad_sads(const uchar16 block2[8],
                                                      __global const uchar* w, int stride) {
  uchar8 row[11];
  _Pragma("unroll") for (int r = 0; r < 11; ++r) row[r] = vload8(0, w + r * stride);
  uchar16 u[10];
  _Pragma("unroll") for (int j = 0; j < 10; ++j) u[j] = (uchar16)(row[j], row[j + 1]);
  ushort16 upper = (ushort16)(0), lower = (ushort16)(0);
  _Pragma("unroll") for (int r = 0; r < 8; ++r) {
    upper += convert_ushort16(max(u[r], block2[r]) - min(u[r], block2[r]));
    lower += convert_ushort16(max(u[r + 2], block2[r]) - min(u[r + 2], block2[r]));
  }
  // The four horizontal sums as one pairwise-add tree (ushort holds a block SAD, <= 16320).
  const ushort16 pairs = (ushort16)(upper.even, lower.even) + (ushort16)(upper.odd, lower.odd);
  const ushort8 quads = pairs.even + pairs.odd;
  return convert_uint4(quads.even + quads.odd);
}

// The minimum key over all (2S+1)^2 candidates; `origin` is the top-left pixel of (-S, -S).
// Candidate rows go four at a time (quad_sads), the last (2S+1) mod 4 one candidate at a time.
// Keys make the order of evaluation irrelevant: the minimum is the first lowest SAD in raster
// order either way.
inline uint best_key_global(const uchar8 block[8], __global const uchar* origin, int width,
                            int radius) {
  const int span = 2 * radius + 1;
  uchar16 block2[8];
  for (int r = 0; r < 8; ++r) block2[r] = (uchar16)(block[r], block[r]);
  uint best = 0xFFFFFFFFu;
  int dy = 0;
  for (; dy + 3 < span; dy += 4) {
    for (int dx = 0; dx < span; ++dx) {
      const uint4 sad = quad_sads(block2, origin + dy * width + dx, width);
      const uint4 key =
          (sad << KEY_INDEX_BITS) | ((uint4)(dy * span + dx) + (uint4)(0, 1, 2, 3) * (uint)span);
      best = min(best, min(min(key.s0, key.s1), min(key.s2, key.s3)));
    }
  }
  for (; dy < span; ++dy) {
    for (int dx = 0; dx < span; ++dx) {
      const uint sad = block_sad___global(block, origin + dy * width + dx, width);
      best = min(best, (sad << KEY_INDEX_BITS) | (uint)(dy * span + dx));
    }
  }
  return best;
}

// The search from S = LANES_MIN_RADIUS on: candidates are the lanes of a plain scalar loop, which
// LLVM's loop vectorizer (PoCL's compiler) runs LANES at a time; PoCL vectorizes no loop of the
// quad search above (docs/opencl.md, "Why OpenCL on PoCL is a fraction of native"). The window
// (2S+8)^2 of `next` is copied into private memory with row stride side = 2S+8, so candidate
// (dx, dy) is lane k = dy * side + dx and reads pixel (c, r) at win[k + r * side + c]: for every
// pixel the lanes are consecutive bytes, one vector load. Lanes with dx >= 2S+1 are no candidates
// (7 of every side lanes), so the share of useful lanes grows with S: 81 of 160 at S = 4, 289 of
// 416 at S = 8, 3969 of 4416 at S = 31; the quad search is as fast at S = 4, this one faster from
// S = 5 (docs/measurements/opencl-kernel.md, 2026-12-08). Those lanes get SAD 0xFFFF, which
// no 8x8 SAD reaches. SAD = 2 sum(max(p, q)) - sum(p) - sum(q), exact as |p - q| = 2 max(p, q)
// - p - q, in ushort arithmetic (2 * 64 * 255 < 2^16); sum(p) is the block's, sum(q) the window's
// 8x8 box sum per lane (column sums, then eight of them). The minimum of (SAD << 13) | k is the
// lowest SAD, then the first candidate in raster order, since k grows with dy, then dx.
#define LANES_MIN_RADIUS 5
#define LANES 32
// The arrays are sized for SPEC's largest S, PXFLOW_MAX_RADIUS, which the host passes as a build
// option (cl::kernel_options); at S = 31 the last lane in use is k = 62 * 70 + 63 = 4403.
#ifndef PXFLOW_MAX_RADIUS
#error "build with the host's options, cl::kernel_options(): -DPXFLOW_MAX_RADIUS=..."
#endif
#define LANES_MAX_SIDE (2 * PXFLOW_MAX_RADIUS + 8)
#define LANES_MAX_USED (2 * PXFLOW_MAX_RADIUS * LANES_MAX_SIDE + 2 * PXFLOW_MAX_RADIUS + 1)
#define LANES_MAX ((LANES_MAX_USED + LANES - 1) / LANES * LANES)
#define LANE_BITS 13
#if LANES_MAX > (1 << LANE_BITS)
#error "a lane index k needs more than LANE_BITS bits"
#endif
// Left to itself LLVM chose 16 lanes, and the kernel took 1.16-1.36x as long (measured). Only
// for Clang: another compiler may warn about an unknown pragma, and the build test uses -Werror.
#ifdef __clang__
#define LANES_VECTORIZE _Pragma("clang loop vectorize_width(32) interleave_count(1)")
#else
#define LANES_VECTORIZE
#endif

__attribute__((always_inline)) inline uint best_key_lanes(const uchar8 block[8],
                                                          __global const uchar* origin, int width,
                                                          int radius) {
  const size_t span = 2 * radius + 1, side = span + 7;
  const size_t n = (span - 1) * side + span, lanes = (n + LANES - 1) / LANES * LANES;
  uchar blk[64];
  ushort block_sum = 0;
  for (int r = 0; r < 8; ++r) {
    vstore8(block[r], r, blk);
    block_sum += (ushort)lane_sum(convert_ushort8(block[r]));
  }
  // Lane k reads win[k + 7 * side + 7] at most (its SAD and its column sums): side * side - 1 for
  // the last candidate, k = n - 1, and below side * side + LANES for every k < lanes. The LANES
  // bytes after the window are zeros; the lanes that read them are no candidates.
  uchar win[LANES_MAX_SIDE * LANES_MAX_SIDE + LANES];
  ushort colsum[LANES_MAX + 7], sad[LANES_MAX];
  for (size_t r = 0; r < side; ++r)
    for (size_t c = 0; c < side; ++c) win[r * side + c] = origin[r * width + c];
  for (size_t c = 0; c < LANES; ++c) win[side * side + c] = 0;
  for (size_t j = 0; j < lanes + 7; ++j) {
    ushort s = 0;
    _Pragma("unroll") for (size_t r = 0; r < 8; ++r) s += win[j + r * side];
    colsum[j] = s;
  }
  for (size_t k0 = 0; k0 < lanes; k0 += LANES) {
    LANES_VECTORIZE for (size_t l = 0; l < LANES; ++l) {
      const size_t k = k0 + l;
      ushort max_sum = 0, box = 0;
      _Pragma("unroll") for (size_t r = 0; r < 8; ++r) {
        _Pragma("unroll") for (size_t c = 0; c < 8; ++c) {
          const uchar p = blk[r * 8 + c], q = win[k + r * side + c];
          max_sum += (ushort)(p > q ? p : q);
        }
      }
      _Pragma("unroll") for (size_t c = 0; c < 8; ++c) box += colsum[k + c];
      sad[k] = (ushort)((ushort)(max_sum + max_sum) - (ushort)(box + block_sum));
    }
  }
  for (size_t dy = 0; dy + 1 < span; ++dy)
    for (size_t dx = span; dx < side; ++dx) sad[dy * side + dx] = 0xFFFF;
  for (size_t k = n; k < lanes; ++k) sad[k] = 0xFFFF;
  uint best = 0xFFFFFFFFu;
  for (size_t k = 0; k < lanes; ++k) best = min(best, ((uint)sad[k] << LANE_BITS) | (uint)k);
  const uint k = best & ((1u << LANE_BITS) - 1u), dy = k / (uint)side, dx = k % (uint)side;
  return ((best >> LANE_BITS) << KEY_INDEX_BITS) | (dy * (uint)span + dx);
}

// One work-item per POI: global memory, and from S = 5 on a private copy of the window
// (best_key_lanes). Launched with at least pairs * POIs-per-pair work-items; `total` is that exact
// count.
__kernel void flow_item_per_poi(__global const uchar* frames, __global uint* records, int width,
                                int height, int radius, uint feature_threshold, uint sad_threshold,
                                int4 grid_x, int4 grid_y, uint total) {
  const uint item = get_global_id(0);
  if (item >= total) return;
  const uint pois = (uint)(grid_x.s2 * grid_y.s2);
  const size_t plane = (size_t)width * (size_t)height;
  __global const uchar* prev = frames + (size_t)(item / pois) * 2 * plane;
  __global const uchar* next = prev + plane;
  const Poi poi = grid_poi(item % pois, radius, grid_x, grid_y);
  __global uint* out = records + (size_t)item * 8;

  uchar8 block[8];
  for (int r = 0; r < 8; ++r) block[r] = vload8(0, prev + (poi.y + r) * width + poi.x);
  const uint feature = feature_of(block);
  if (feature < feature_threshold) {
    store_dropped(out, poi, feature);
    return;
  }
  const int span = 2 * radius + 1;
  __global const uchar* origin = next + (poi.y - radius) * width + poi.x - radius;
  const uint key = radius >= LANES_MIN_RADIUS ? best_key_lanes(block, origin, width, radius)
                                              : best_key_global(block, origin, width, radius);
  const uint index = key & KEY_INDEX_MASK, best = key >> KEY_INDEX_BITS;
  const int bx = (int)(index % (uint)span) - radius, by = (int)(index / (uint)span) - radius;
  uint sub[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  uint status = STATUS_REJECTED, dir = DIR_NONE;
  if (best < sad_threshold) {
    half_pixel_sads___global(block, next + (poi.y + by) * width + poi.x + bx, width, sub);
    status = STATUS_ACCEPTED;
    dir = vote(best, sub);
  }
  store_record(out, poi, status, feature, bx, by, best, dir, sub);
}
