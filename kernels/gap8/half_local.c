/* Variant "local": per accepted POI, the planes h, g, d over the matched block plus a one-pixel
 * border (10x10, block coordinates -1..8) once, four cells at a time, then the eight directions
 * read them (the paper's 300 interpolations per POI). The planes live on the core's stack. */
#include "flow_kernel.h"
#include "half_planes.h"

const uint32_t variant_planes = 0;

/* The planes, one array: h (10 rows of 3 words), g (the same), one scratch row, d (10 rows). The
 * loop below writes d's row v-1 with h's row v, so its first iteration writes d's row -1: the
 * scratch row, never read. */
enum { kSide = 10, kPitch = 12, kPlane = kSide * kPitch }; /* 10 cells per row, 3 words */
enum { kH = 0, kG = kPlane, kD = 2 * kPlane + kPitch, kBytes = kD + kPlane };

void variant_prepare(const flow_ctx *c, uint32_t core) {
  (void)c;
  (void)core;
}

/* Row v of the planes holds block row v-1, word q its cells u = 4q-1 .. 4q+2. The cells of the
 * far border (u or v = 8, 9, 10) read pixels no direction needs: computed, never read (d's row
 * 9 is not even computed). One hardware loop over the 10 rows; each iteration reads three words
 * of the frame rows v-1 and v (9 loads), computes h and g of row v and d of row v-1 from h of
 * rows v-1 (kept in registers) and v (nine floor averages, FLOOR_AVG_ASM), and stores the nine
 * words. */
static void build_planes(uint8_t *planes, const uint8_t *p, uint32_t w) {
  const uint8_t *pn = p + w;
  uint32_t a0, a1, a2, b0, b1, b2, c0, c1, c2, h0, h1, h2, t;
  /* clang-format off */
  __asm__ volatile(
      GAP8_ASM_HWLOOP_BEGIN
      /* loop 0: body of 57 instructions, the last 228 bytes (114 half-words) after lp.setup */
      ".Lstart%=: " GAP8_ASM_LP_SETUP("0", "%[rows]", "114")
      "lw %[b0], 1(%[p])\n\t"   "lw %[b1], 5(%[p])\n\t"   "lw %[b2], 9(%[p])\n\t"
      "lw %[a1], 4(%[p])\n\t"   "lw %[a2], 8(%[p])\n\t"
      GAP8_ASM_P_LW_POST_REG("%[a0]", "%[w]", "%[p]")   /* P(u, v-1), then the next row */
      "lw %[c1], 4(%[pn])\n\t"  "lw %[c2], 8(%[pn])\n\t"
      GAP8_ASM_P_LW_POST_REG("%[c0]", "%[w]", "%[pn]")  /* P(u, v) */
      FLOOR_AVG_ASM("%[b0]", "%[a0]", "%[b0]", "%[t]")     /* h of row v */
      FLOOR_AVG_ASM("%[b1]", "%[a1]", "%[b1]", "%[t]")
      FLOOR_AVG_ASM("%[b2]", "%[a2]", "%[b2]", "%[t]")
      FLOOR_AVG_ASM("%[c0]", "%[a0]", "%[c0]", "%[t]")     /* g of row v */
      FLOOR_AVG_ASM("%[c1]", "%[a1]", "%[c1]", "%[t]")
      FLOOR_AVG_ASM("%[c2]", "%[a2]", "%[c2]", "%[t]")
      FLOOR_AVG_ASM("%[h0]", "%[h0]", "%[b0]", "%[t]")     /* d of row v-1 */
      FLOOR_AVG_ASM("%[h1]", "%[h1]", "%[b1]", "%[t]")
      FLOOR_AVG_ASM("%[h2]", "%[h2]", "%[b2]", "%[t]")
      "sw %[b1], 4(%[ph])\n\t"   "sw %[b2], 8(%[ph])\n\t"
      "sw %[c0], %[g](%[ph])\n\t" "sw %[c1], %[g]+4(%[ph])\n\t" "sw %[c2], %[g]+8(%[ph])\n\t"
      "sw %[h0], %[d](%[ph])\n\t" "sw %[h1], %[d]+4(%[ph])\n\t" "sw %[h2], %[d]+8(%[ph])\n\t"
      GAP8_ASM_P_SW_POST_IMM("%[b0]", "12", "%[ph]")
      "mv %[h0], %[b0]\n\t" "mv %[h1], %[b1]\n\t"
      ".Lend%=: mv %[h2], %[b2]\n\t"
      GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lend%=", "228")
      GAP8_ASM_HWLOOP_END
      : [p] "+r"(p), [pn] "+r"(pn), [ph] "+r"(planes), [a0] "=&r"(a0), [a1] "=&r"(a1),
        [a2] "=&r"(a2), [b0] "=&r"(b0), [b1] "=&r"(b1), [b2] "=&r"(b2), [c0] "=&r"(c0),
        [c1] "=&r"(c1), [c2] "=&r"(c2), [h0] "=&r"(h0), [h1] "=&r"(h1), [h2] "=&r"(h2),
        [t] "=&r"(t)
      : [w] "r"(w), [rows] "r"((uint32_t)kSide), [g] "i"(kG - kH), [d] "i"(kD - kPitch - kH)
      : "memory");
  /* clang-format on */
}

void variant_half_sads(const flow_ctx *c, const uint8_t *blk, uint32_t mx, uint32_t my,
                       uint32_t sub[8]) {
  const uint32_t w = c->width;
  uint32_t words[kBytes / 4];
  uint8_t *planes = (uint8_t *)words;
  build_planes(planes, c->next + (my - 1) * w + mx - 1, w);
  /* Cell (0, 0) of the block is row 1, byte 1. */
  const int origin = kPitch + 1;
  sads_from_planes(blk, w, planes + kH + origin, planes + kG + origin, planes + kD + origin, kPitch,
                   sub);
}
