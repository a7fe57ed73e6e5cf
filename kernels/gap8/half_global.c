/* Variant "global": before any matching, the team computes the planes h, g, d of the whole next
 * frame into L1 (W*H*3 interpolations, rows split over the cores round robin), then each
 * accepted POI only reads them. The planes' last column (h) and row (g, d) would need pixels
 * beyond the frame: they are computed from the buffers' slack and never read (SPEC §3). */
#include <pmsis.h>

#include "flow_kernel.h"
#include "half_planes.h"

const uint32_t variant_planes = 3;

/* One plane row from `src` rows (y, y+1): word-wide, then the W % 4 tail pixel by pixel, so
 * that no core writes into a row another core owns. The word-wide part is a hardware loop, two
 * words per iteration (so that no average waits for the load just before it), post-increment
 * loads and stores; each average is FLOOR_AVG_ASM (4 instructions). */
static void average_row(uint8_t *dst, const uint8_t *a, const uint8_t *b, uint32_t w) {
  const uint32_t pairs = w / 8;
  if (pairs != 0) {
    uint32_t a0, a1, b0, b1, t;
    /* clang-format off */
    __asm__ volatile(
        GAP8_ASM_HWLOOP_BEGIN
        /* loop 0: body of 14 instructions, the last 56 bytes (28 half-words) after lp.setup */
        ".Lstart%=: " GAP8_ASM_LP_SETUP("0", "%[n]", "28")
        /* one line per step: the two rows' word k, their word k+1, both averages, stores */
        GAP8_ASM_P_LW_POST_IMM("%[a0]", "4", "%[pa]") GAP8_ASM_P_LW_POST_IMM("%[b0]", "4", "%[pb]")
        GAP8_ASM_P_LW_POST_IMM("%[a1]", "4", "%[pa]") GAP8_ASM_P_LW_POST_IMM("%[b1]", "4", "%[pb]")
        FLOOR_AVG_ASM("%[a0]", "%[a0]", "%[b0]", "%[t]") FLOOR_AVG_ASM("%[a1]", "%[a1]", "%[b1]", "%[t]")
        GAP8_ASM_P_SW_POST_IMM("%[a0]", "4", "%[pd]")
        ".Lend%=: " GAP8_ASM_P_SW_POST_IMM("%[a1]", "4", "%[pd]")
        GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lend%=", "56")
        GAP8_ASM_HWLOOP_END
        : [pa] "+r"(a), [pb] "+r"(b), [pd] "+r"(dst), [a0] "=&r"(a0), [a1] "=&r"(a1),
          [b0] "=&r"(b0), [b1] "=&r"(b1), [t] "=&r"(t)
        : [n] "r"(pairs)
        : "memory");
    /* clang-format on */
  }
  uint32_t x = 8 * pairs;
  if (x + 4 <= w) {
    st4(dst, avg4(ld4(a), ld4(b)));
    dst += 4, a += 4, b += 4, x += 4;
  }
  for (uint32_t i = 0; x + i < w; ++i) dst[i] = (uint8_t)((a[i] + b[i]) >> 1);
}

void variant_prepare(const flow_ctx *c, uint32_t core) {
  const uint32_t w = c->width, h = c->height;
  uint8_t *hp = c->planes[0], *gp = c->planes[1], *dp = c->planes[2];
  for (uint32_t y = core; y < h; y += c->cores) {
    const uint8_t *row = c->next + y * w;
    average_row(hp + y * w, row, row + 1, w); /* h(x, y) = avg(P(x, y), P(x+1, y)) */
    average_row(gp + y * w, row, row + w, w); /* g(x, y) = avg(P(x, y), P(x, y+1)) */
  }
  pi_cl_team_barrier(); /* d reads h of the next row, which another core may own */
  for (uint32_t y = core; y < h; y += c->cores)
    average_row(dp + y * w, hp + y * w, hp + (y + 1) * w, w);
  pi_cl_team_barrier();
}

void variant_half_sads(const flow_ctx *c, const uint8_t *blk, uint32_t mx, uint32_t my,
                       uint32_t sub[8]) {
  const uint32_t w = c->width, at = my * w + mx;
  sads_from_planes(blk, w, c->planes[0] + at, c->planes[1] + at, c->planes[2] + at, (int)w, sub);
}
