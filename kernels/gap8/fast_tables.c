/* The fast variant's per-frame tables (fast_tables.h), built by the whole team before the POIs:
 * first the three shifted copies of next (words interleaved over the cores), a barrier, then the
 * negated 8x8 block sums (columns of the search windows over the cores), a barrier. */
#include "fast_tables.h"

#include <pmsis.h>

#include "flow_simd.h"

PI_L1 fast_tables g_fast = {0};

const uint32_t variant_planes = 0;

/* Words [first, first + n) of the copies 1..3: copy[q] word i = the (misaligned) word of next at
 * byte 4i + q. One hardware loop, post-increment loads and stores. */
static void copy_words(const uint8_t *next, uint8_t *const copy[4], uint32_t first, uint32_t n) {
  const uint8_t *s1 = next + 4 * first + 1, *s2 = s1 + 1, *s3 = s1 + 2;
  uint8_t *d1 = copy[1] + 4 * first, *d2 = copy[2] + 4 * first, *d3 = copy[3] + 4 * first;
  uint32_t t0, t1, t2;
  /* clang-format off */
  __asm__ volatile(
      GAP8_ASM_HWLOOP_BEGIN
      /* loop 0: body of 6 instructions, the last 24 bytes (12 half-words) after lp.setup */
      ".Lstart%=: " GAP8_ASM_LP_SETUP("0", "%[n]", "12")
      GAP8_ASM_P_LW_POST_IMM("%[t0]", "4", "%[s1]")
      GAP8_ASM_P_LW_POST_IMM("%[t1]", "4", "%[s2]")
      GAP8_ASM_P_LW_POST_IMM("%[t2]", "4", "%[s3]")
      GAP8_ASM_P_SW_POST_IMM("%[t0]", "4", "%[d1]")
      GAP8_ASM_P_SW_POST_IMM("%[t1]", "4", "%[d2]")
      ".Lend%=: " GAP8_ASM_P_SW_POST_IMM("%[t2]", "4", "%[d3]")
      GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lend%=", "24")
      GAP8_ASM_HWLOOP_END
      : [s1] "+r"(s1), [s2] "+r"(s2), [s3] "+r"(s3), [d1] "+r"(d1), [d2] "+r"(d2),
        [d3] "+r"(d3), [t0] "=&r"(t0), [t1] "=&r"(t1), [t2] "=&r"(t2)
      : [n] "r"(n)
      : "memory");
  /* clang-format on */
}

/* Sum of the 8 pixels at the aligned word pointer w (this row's words w[0], w[1]). */
static inline uint32_t row8(const uint8_t *w) {
  return gap8_pv_sdotup_sc_b(gap8_pv_dotup_sc_b(ld4(w), 1u), ld4(w + 4), 1u);
}

/* The column of block sums at x for the rows y0 .. y0 + 8 * blocks (W = kFastWidth): `w` points
 * at next's row y0, bytes x .. x+7, word-aligned in copy[x & 3]; `out` at neg_box[y0 * W + x].
 * nB(y + 1) = nB(y) + R(y) - R(y + 8), R(y) the row sum of row y; the 8 R of the current window
 * live in registers r0..r7 (a ring: step k replaces R(y) by R(y + 8)). One hardware loop of 8
 * steps per iteration; the last iteration may run past the rows needed (it writes table rows
 * that are never read and reads L1 beyond the frame, never outside L1). */
static void box_column(const uint8_t *w, uint32_t *out, uint32_t blocks) {
  enum { kRow = kFastWidth, kOutRow = 4 * kFastWidth };
  uint32_t r0 = row8(w), r1 = row8(w + kRow), r2 = row8(w + 2 * kRow), r3 = row8(w + 3 * kRow);
  uint32_t r4 = row8(w + 4 * kRow), r5 = row8(w + 5 * kRow), r6 = row8(w + 6 * kRow);
  uint32_t r7 = row8(w + 7 * kRow);
  uint32_t nb = 0u - (r0 + r1 + r2 + r3 + r4 + r5 + r6 + r7);
  out[0] = nb;
  uint32_t *pt = out + kFastWidth; /* row y0 + 1 */
  const uint32_t one = 1, step = 8 * kOutRow;
  uint32_t a0, a1;
  /* One step: row y+8's two words, nB += R(y), R(y) := R(y+8), nB -= R(y+8), store nB(y+1). */
  /* clang-format off */
#define BOX_STEP(k, rk)                                                                        \
  "lw %[a0], 8*64+64*" #k "(%[w])\n\t"                                                         \
  "lw %[a1], 8*64+64*" #k "+4(%[w])\n\t"                                                       \
  "add %[nb], %[nb], " rk "\n\t"                                                               \
  GAP8_ASM_PV_DOTUP_SC_B(rk, "%[a0]", "%[one]")                                                \
  GAP8_ASM_PV_SDOTUP_SC_B(rk, "%[a1]", "%[one]")                                               \
  "sub %[nb], %[nb], " rk "\n\t"                                                               \
  "sw %[nb], 256*" #k "(%[pt])\n\t"
  __asm__ volatile(
      GAP8_ASM_HWLOOP_BEGIN
      /* loop 0: body of 58 instructions, the last 232 bytes (116 half-words) after lp.setup */
      ".Lstart%=: " GAP8_ASM_LP_SETUP("0", "%[n]", "116")
      BOX_STEP(0, "%[r0]") BOX_STEP(1, "%[r1]") BOX_STEP(2, "%[r2]") BOX_STEP(3, "%[r3]")
      BOX_STEP(4, "%[r4]") BOX_STEP(5, "%[r5]") BOX_STEP(6, "%[r6]") BOX_STEP(7, "%[r7]")
      "addi %[w], %[w], 8*64\n\t"
      ".Lend%=: add %[pt], %[pt], %[step]\n\t"
      GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lend%=", "232")
      GAP8_ASM_HWLOOP_END
      : [w] "+r"(w), [pt] "+r"(pt), [nb] "+r"(nb), [r0] "+r"(r0), [r1] "+r"(r1), [r2] "+r"(r2),
        [r3] "+r"(r3), [r4] "+r"(r4), [r5] "+r"(r5), [r6] "+r"(r6), [r7] "+r"(r7),
        [a0] "=&r"(a0), [a1] "=&r"(a1)
      : [n] "r"(blocks), [one] "r"(one), [step] "r"(step)
      : "memory");
#undef BOX_STEP
  /* clang-format on */
}

/* The L1 the tables need: three copies and a W x H word table. */
static uint32_t tables_bytes(const flow_ctx *c) {
  return 3 * pxflow_gap8_frame_l1_bytes(c->width, c->height) + 4 * c->width * c->height;
}

void variant_prepare(const flow_ctx *c, uint32_t core) {
  const uint32_t w = c->width, h = c->height, s = c->search_radius;
  fast_team_begin(c, core);
  if (w != kFastWidth || c->pois == 0) { /* same decision on every core */
    team_sync();
    return;
  }
  if (core == 0) {
    if (!g_fast.tried) {
      g_fast.tried = 1;
      uint8_t *l1 = pi_cl_l1_malloc(0, tables_bytes(c));
      if (l1) {
        const uint32_t frame = pxflow_gap8_frame_l1_bytes(w, h);
        for (uint32_t q = 1; q < 4; ++q) g_fast.copy[q] = l1 + (q - 1) * frame;
        g_fast.neg_box = (uint32_t *)(l1 + 3 * frame);
      }
    }
    g_fast.copy[0] = c->next;
    g_fast.ready = 0;
  }
  team_sync();
  if (!g_fast.neg_box) return; /* no L1 for the tables: the held-register search */
  /* Copies: core k takes words [k * chunk, (k + 1) * chunk); chunk = 1 mod 16, so that cores in
   * lockstep touch different TCDM banks. */
  const uint32_t words = w * h / 4, cores = c->cores;
  const uint32_t chunk = (((words + cores - 1) / cores + 14) & ~15u) + 1;
  const uint32_t first = core * chunk;
  if (first < words) {
    const uint32_t n = words - first < chunk ? words - first : chunk;
    copy_words(c->next, (uint8_t *const *)g_fast.copy, first, n);
  }
  team_sync();
  /* Block sums over the union of the search windows: columns round robin over the cores. */
  const uint16_t *last = c->poi_xy + 2 * (c->pois - 1);
  const uint32_t x_lo = c->poi_xy[0] - s, x_hi = last[0] + s;
  const uint32_t y_lo = c->poi_xy[1] - s, y_hi = last[1] + s;
  const uint32_t blocks = (y_hi - y_lo + 7) / 8; /* >= 1: y_hi - y_lo >= 2S >= 2 */
  for (uint32_t x = x_lo + core; x <= x_hi; x += cores)
    box_column(g_fast.copy[x & 3] + y_lo * w + (x & ~3u), g_fast.neg_box + y_lo * w + x, blocks);
  if (core == 0) g_fast.ready = 1;
  team_sync();
}
