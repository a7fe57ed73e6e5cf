// pxflow kernel (SPEC §3) as a Vulkan compute shader: one invocation per point of interest.
//
// Why one invocation per POI: the per-POI work (feature, (2S+1)^2 candidate SADs, eight
// half-pixel SADs) is independent, so no shared memory, no barriers and no reduction are needed,
// and the raster-order tie rule is just the sequential loop of the reference. On lavapipe the
// invocations of a work-group become the SIMD lanes of the JIT-compiled loop; on a GPU a batch of
// frame pairs supplies the parallelism (4096 pairs x 64 POIs = 262,144 invocations).
//
// No 8-bit storage or shaderInt8: a frame is a run of 32-bit words holding 4 pixels each (pixel n
// in byte n & 3 of word n >> 2, little-endian), and every value is handled as 4 packed bytes, like
// the firmware's USAD8 / UHADD8 (SPEC §7).
#version 450
#extension GL_EXT_control_flow_attributes : require  // [[unroll]]: see integer_search
#extension GL_GOOGLE_include_directive : require     // shader_checks.glsl

layout(local_size_x_id = 0) in;  // set by the host from the device's work-group limits

// Frame pairs of the current chunk, read through FRAME_WORD(frame, word) (shader_checks.glsl):
// word `word` of the invocation's prev (kPrev) or next (kNext), 4 pixels per word. Each frame
// carries one spare word at its end so that the 4-byte funnel read of the last pixels never leaves
// the frame.
// Read as a uniform texel buffer (R32_UINT, one texel = one word), not a storage buffer: lavapipe
// turns a texel fetch with per-invocation addresses into one vector gather, but a storage-buffer
// read into a per-lane, bounds-checked scalar loop.
layout(set = 0, binding = 0) uniform usamplerBuffer frame_texels;

// One 32-byte record (reference/record.hpp) = 8 little-endian words per POI, pair after pair.
layout(std430, set = 0, binding = 1) writeonly buffer Records { uint record_words[]; };

layout(push_constant) uniform Problem {
  uint width;              // W = row stride in pixels (S is the specialization constant S)
  uint feature_threshold;  // FT
  uint sad_threshold;      // VT
  uint grid_x0;            // first POI column, column step, POIs per grid row (SPEC §2)
  uint grid_step_x;
  uint grid_nx;
  uint grid_y0;  // first POI row, row step
  uint grid_step_y;
  uint pois_per_pair;
  uint words_per_frame;
  uint first_item;  // this dispatch's first POI, counted over the chunk (pair-major)
  uint item_count;  // POIs in this dispatch
}
pc;

// The shader's checks of itself, on in the checked build only: AT(array, index) for every dynamic
// private-array index, FRAME_WORD(frame, word) for every frame read, POISON(array) for each array.
#include "shader_checks.glsl"

// The 4 pixels starting at byte sh / 8 of the 8-byte little-endian string lo, hi (sh = 0, 8, 16
// or 24). (hi << 1) << (31 - sh) is hi << (32 - sh) without the undefined shift by 32 when sh == 0.
uint funnel(uint lo, uint hi, uint sh) { return (lo >> sh) | ((hi << 1u) << (31u - sh)); }

// Why every row is read once and then shifted in registers: on lavapipe each storage-buffer read
// with a per-invocation address is a per-lane, bounds-checked scalar loop, so reads, not the SAD
// arithmetic, dominated the first versions (docs/vulkan.md, "Benchmark").

// The 8 pixels n .. n+7 of `frame` (kPrev or kNext), as two packed words.
void load8(uint frame, uint n, out uint w0, out uint w1) {
  uint q = n >> 2;
  uint sh = (n & 3u) * 8u;
  uint a = FRAME_WORD(frame, q);
  uint b = FRAME_WORD(frame, q + 1u);
  uint c = FRAME_WORD(frame, q + 2u);
  w0 = funnel(a, b, sh);
  w1 = funnel(b, c, sh);
}

// USAD8: sum over the 4 byte lanes of |a_i - b_i|.
uint usad8(uint a, uint b) {
  ivec4 va = ivec4((uvec4(a) >> uvec4(0u, 8u, 16u, 24u)) & 0xFFu);
  ivec4 vb = ivec4((uvec4(b) >> uvec4(0u, 8u, 16u, 24u)) & 0xFFu);
  ivec4 d = abs(va - vb);
  return uint(d.x + d.y + d.z + d.w);
}

// UHADD8: per byte floor((a_i + b_i) / 2). NOT (a+b+1)/2, which rounds up (SPEC §7).
uint uhadd8(uint a, uint b) { return (a & b) + (((a ^ b) & 0xFEFEFEFEu) >> 1); }

// Step 1, the feature test over the central 4x4 of prev's block (columns 2..5 of block rows
// 2..5, cut out of the block's packed words): three vertical row differences and, per row, the
// three horizontal neighbour differences (the top lane of q and q >> 8 is 0 in both, so it adds
// nothing).
uint feature_value(uint blk[16]) {
  uint q[4];
  POISON(q);
  for (int r = 0; r < 4; ++r) AT(q, r) = (AT(blk, 2 * r + 4) >> 16) | (AT(blk, 2 * r + 5) << 16);
  uint sum = 0u;
  for (int r = 0; r < 3; ++r) sum += usad8(AT(q, r), AT(q, r + 1));
  for (int r = 0; r < 4; ++r) sum += usad8(AT(q, r) & 0x00FFFFFFu, AT(q, r) >> 8);
  return sum;
}

// Step 2, the integer search, dy outer, dx inner (raster order). The search window (rows y-S ..
// y+S+7, columns x-S .. x+S+7 of next) is read once per POI, one row per step of the t loop:
// `win` holds the 8 rows under the block at the current dy as packed words, and each step moves
// them up by one row and reads the next. Reading rows per (dy, block row) instead cost 8 times the
// texel fetches (360 against 80 per POI at S = 4), and each fetch is a call to lavapipe's gather
// helper (docs/vulkan.md, "Benchmark"). For one dy and one block row r, the candidates dx = -S..S
// all read the same 2S+8 pixels of next: they are unpacked once into `seg` and every candidate's
// row SAD comes from registers. S is a specialization constant, so the loops over dx, c and the
// segment have constant trip counts, and `win`, `seg` and the sums are registers instead of
// memory. [[unroll]] makes sure of it for the block-row loop: left as a loop, it indexed prev's
// block dynamically and the search was about 20 % slower. The t loop stays a loop (unrolled, it
// compiled for seconds and gained nothing).
layout(constant_id = 1) const int S = 4;
const int kSide = 2 * S + 1;                // candidates per axis
const int kSegWords = (2 * S + 8 + 3) / 4;  // words holding the 2S+8 pixels of one row

// Why max, not abs: |a - b| = 2 max(a, b) - a - b, so SAD(dx, dy) = 2 M - A - N with M the sum of
// max(prev, next) over the block, A the block's pixel sum and N the candidate's: one max and one
// add per pixel instead of a subtract, an abs and an add. N comes from the window's column sums
// under the block (one add per column and block row), run along the row once per dy (two
// operations per candidate), A once per POI. All exact in 32 bits.
// Only a STRICTLY smaller SAD replaces, so ties keep the first candidate in raster order.
// prev's block comes unpacked (`pv`, flow_poi): loop-invariant pixels, which the JIT keeps in
// registers or reloads from the stack.
void integer_search(int pv[64], uint n, out uint best, out int bx, out int by) {
  best = 0xFFFFFFFFu;
  bx = 0;
  by = 0;
  int block_sum = 0;  // A
  [[unroll]] for (int k = 0; k < 64; ++k) block_sum += AT(pv, k);
  // (Arrays sized by S stay in this function: passing them to functions breaks SPIR-V validation.)
  uint win[8 * kSegWords];  // window rows t-7 .. t from column x - S, kSegWords packed words each
  POISON(win);
  uint m = uint(int(n) - S * int(pc.width) - S);  // window row t's first pixel
  // Every loop in the t loop is unrolled: lavapipe ends an invocation after 65,535 loop
  // iterations in all (docs/vulkan.md, "Waiting on a device"), and at S = 31 the t loop's 70
  // steps times its inner loops' iterations (the checked build's poison loops included) passed
  // that and left the records wrong.
  for (int t = 0; t < kSide + 7; ++t) {
    [[unroll]] for (int k = 0; k < 7 * kSegWords; ++k) AT(win, k) = AT(win, k + kSegWords);
    uint q = m >> 2;
    uint sh = (m & 3u) * 8u;
    uint lo = FRAME_WORD(kNext, q);
    [[unroll]] for (int k = 0; k < kSegWords; ++k) {
      uint hi = FRAME_WORD(kNext, q + uint(k) + 1u);
      AT(win, 7 * kSegWords + k) = funnel(lo, hi, sh);
      lo = hi;
    }
    m += pc.width;
    if (t < 7) continue;  // the first 7 rows only fill `win`
    int dy = t - 7 - S;
    int max_sums[kSide];  // M of each candidate dx of this dy
    POISON(max_sums);
    [[unroll]] for (int k = 0; k < kSide; ++k) AT(max_sums, k) = 0;
    int column_sums[kSegWords * 4];  // the 8 window rows under the block, summed per column
    POISON(column_sums);
    [[unroll]] for (int k = 0; k < kSegWords * 4; ++k) AT(column_sums, k) = 0;
    [[unroll]] for (int r = 0; r < 8; ++r) {
      int seg[kSegWords * 4];  // window row t - 7 + r, unpacked
      POISON(seg);
      [[unroll]] for (int k = 0; k < kSegWords; ++k) {
        uint w = AT(win, r * kSegWords + k);
        for (int j = 0; j < 4; ++j) AT(seg, 4 * k + j) = int((w >> (8u * uint(j))) & 0xFFu);
      }
      [[unroll]] for (int k = 0; k < kSegWords * 4; ++k) AT(column_sums, k) += AT(seg, k);
      [[unroll]] for (int dx = 0; dx < kSide; ++dx) {
        for (int c = 0; c < 8; ++c) AT(max_sums, dx) += max(AT(pv, 8 * r + c), AT(seg, dx + c));
      }
    }
    int next_sum = 0;  // N of candidate dx: 8 column sums, running along the row
    [[unroll]] for (int c = 0; c < 8; ++c) next_sum += AT(column_sums, c);
    [[unroll]] for (int k = 0; k < kSide; ++k) {
      if (k > 0) next_sum += AT(column_sums, k + 7) - AT(column_sums, k - 1);
      uint sad = uint(2 * AT(max_sums, k) - next_sum - block_sum);
      if (sad < best) {
        best = sad;
        bx = k - S;
        by = dy;
      }
    }
  }
}

// The packed values of one row of the matched block's neighbourhood, for the 4 columns 4*q ..
// 4*q+3 of block row v: p = P(c, v), h = h(c, v), hl = h(c-1, v) (SPEC §3 notation).
struct HalfRow {
  uint p;
  uint h;
  uint hl;
};

// Both halves (q = 0, 1) of block row v, which starts at pixel m of next. Columns -1 .. 8 are
// read once (4 words) and aligned into `left` = columns -1..2, 3..6, 7..10; the other windows are
// constant byte shifts of those.
void half_rows(uint m, out HalfRow q0, out HalfRow q1) {
  uint a = m - 1u;  // column -1
  uint w = a >> 2;
  uint sh = (a & 3u) * 8u;
  uint w0 = FRAME_WORD(kNext, w);
  uint w1 = FRAME_WORD(kNext, w + 1u);
  uint w2 = FRAME_WORD(kNext, w + 2u);
  uint w3 = FRAME_WORD(kNext, w + 3u);
  uint left0 = funnel(w0, w1, sh);
  uint left1 = funnel(w1, w2, sh);
  uint left2 = funnel(w2, w3, sh);
  uint here0 = (left0 >> 8) | (left1 << 24);
  uint right0 = (left0 >> 16) | (left1 << 16);
  uint here1 = (left1 >> 8) | (left2 << 24);
  uint right1 = (left1 >> 16) | (left2 << 16);
  q0 = HalfRow(here0, uhadd8(here0, right0), uhadd8(left0, here0));
  q1 = HalfRow(here1, uhadd8(here1, right1), uhadd8(left1, here1));
}

// The SAD of 4 unpacked pixels p of prev against 4 packed values v.
uint sad4(ivec4 p, uint v) {
  ivec4 d = abs(p - ivec4((uvec4(v) >> uvec4(0u, 8u, 16u, 24u)) & 0xFFu));
  return uint(d.x + d.y + d.z + d.w);
}

// One block row's 4 unpacked pixels b against the eight direction values built from rows r-1, r,
// r+1 of next. The diagonal d(u, v) is the floor average of two floored HORIZONTAL averages.
void add_half_sads(ivec4 b, HalfRow up, HalfRow mid, HalfRow down, inout uint sub[8]) {
  sub[0] += sad4(b, mid.h);                    // h(c, r)
  sub[1] += sad4(b, uhadd8(mid.h, down.h));    // d(c, r)
  sub[2] += sad4(b, uhadd8(mid.p, down.p));    // g(c, r)
  sub[3] += sad4(b, uhadd8(mid.hl, down.hl));  // d(c-1, r)
  sub[4] += sad4(b, mid.hl);                   // h(c-1, r)
  sub[5] += sad4(b, uhadd8(up.hl, mid.hl));    // d(c-1, r-1)
  sub[6] += sad4(b, uhadd8(up.p, mid.p));      // g(c, r-1)
  sub[7] += sad4(b, uhadd8(up.h, mid.h));      // d(c, r-1)
}

// Step 3: the eight half-pixel SADs around the integer match at pixel n of next. Rows -1 .. 8 of
// next are read once each, rolling down the block (up, mid, down).
void half_pixel_sads(int pv[64], uint n, out uint sub[8]) {
  POISON(sub);
  for (int k = 0; k < 8; ++k) AT(sub, k) = 0u;
  HalfRow up0, up1, mid0, mid1, down0, down1;
  half_rows(n - pc.width, up0, up1);
  half_rows(n, mid0, mid1);
  [[unroll]] for (int r = 0; r < 8; ++r) {
    half_rows(n + uint(r + 1) * pc.width, down0, down1);
    int c = 8 * r;
    ivec4 left = ivec4(AT(pv, c), AT(pv, c + 1), AT(pv, c + 2), AT(pv, c + 3));
    ivec4 right = ivec4(AT(pv, c + 4), AT(pv, c + 5), AT(pv, c + 6), AT(pv, c + 7));
    add_half_sads(left, up0, mid0, down0, sub);
    add_half_sads(right, up1, mid1, down1, sub);
    up0 = mid0;
    up1 = mid1;
    mid0 = down0;
    mid1 = down1;
  }
}

// PoiRecord::status and dir values and the step table: the spec core's
// (spec/include/pxflow_spec/record.h), spelled in GLSL and checked by ctest spec_copies.
const uint kStatusDropped = 0u;   // feature < FT
const uint kStatusRejected = 1u;  // best integer SAD >= VT
const uint kStatusAccepted = 2u;
const uint kDirNone = 8u;  // the integer match won the half-pixel vote

// Half-pixel step (sx, sy) of direction k (SPEC §3 table); k = kDirNone is the integer match.
const int kStepX[9] = int[9](1, 1, 0, -1, -1, -1, 0, 1, 0);
const int kStepY[9] = int[9](0, 1, 1, 1, 0, -1, -1, -1, 0);

uint pack_i8(int lo, int hi) { return (uint(lo) & 0xFFu) | ((uint(hi) & 0xFFu) << 8); }

void write_record(uint item, uint x, uint y, uint status, uint feature, int bx, int by, uint sad,
                  uint dir, uint sub[8], int hx, int hy) {
  uint o = item * 8u;
  record_words[o + 0u] = x | (y << 16);
  record_words[o + 1u] = status | (feature << 16);  // pad0 = 0
  record_words[o + 2u] = pack_i8(bx, by) | (sad << 16);
  record_words[o + 3u] = dir | (sub[0] << 16);  // pad1 = 0
  record_words[o + 4u] = sub[1] | (sub[2] << 16);
  record_words[o + 5u] = sub[3] | (sub[4] << 16);
  record_words[o + 6u] = sub[5] | (sub[6] << 16);
  record_words[o + 7u] = sub[7] | (pack_i8(hx, hy) << 16);
}

// One POI: steps 1-3 and its record.
void flow_poi() {
  if (gl_GlobalInvocationID.x >= pc.item_count) return;
  uint item = pc.first_item + gl_GlobalInvocationID.x;
  uint poi = item % pc.pois_per_pair;
  uint x = pc.grid_x0 + (poi % pc.grid_nx) * pc.grid_step_x;
  uint y = pc.grid_y0 + (poi / pc.grid_nx) * pc.grid_step_y;
  uint n = y * pc.width + x;  // the POI's top-left pixel
  uint zero[8] = uint[8](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);

  // prev's 8x8 block, 2 packed words per row, read once for all three steps.
  uint blk[16];
  POISON(blk);
  for (int r = 0; r < 8; ++r)
    load8(kPrev, n + uint(r) * pc.width, AT(blk, 2 * r), AT(blk, 2 * r + 1));

  uint feature = feature_value(blk);
  int pv[64];  // the same block unpacked, pixel (c, r) at 8 r + c, for the search and step 3
  POISON(pv);
  [[unroll]] for (int k = 0; k < 64; ++k) {
    AT(pv, k) = int((AT(blk, k >> 2) >> (8u * uint(k & 3))) & 0xFFu);
  }
  if (feature < pc.feature_threshold) {
    write_record(item, x, y, kStatusDropped, feature, 0, 0, 0u, kDirNone, zero, 0, 0);
    return;
  }

  uint best;
  int bx;
  int by;
  integer_search(pv, n, best, bx, by);
  if (!(best < pc.sad_threshold)) {
    write_record(item, x, y, kStatusRejected, feature, bx, by, best, kDirNone, zero, 0, 0);
    return;
  }

  uint sub[8];
  half_pixel_sads(pv, uint(int(n) + by * int(pc.width) + bx), sub);
  // The vote starts from the integer match (kDirNone); k = 0..7 replaces only when strictly
  // smaller.
  uint vote = best;
  uint dir = kDirNone;
  for (uint k = 0u; k < 8u; ++k) {
    if (AT(sub, k) < vote) {
      vote = AT(sub, k);
      dir = k;
    }
  }
  write_record(item, x, y, kStatusAccepted, feature, bx, by, best, dir, sub,
               2 * bx + AT(kStepX, dir), 2 * by + AT(kStepY, dir));
}

void main() {
  flow_poi();
  report_shader_faults();
}
