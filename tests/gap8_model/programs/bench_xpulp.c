/* Benchmark load for the simulator's Xpulp dispatch: the same 8x8 sums of absolute differences
 * as bench.c, four pixels at a time with the kernels' instructions (p.lw post-increment,
 * pv.minu.b / pv.maxu.b / pv.sub.b, pv.sdotup.b: the interpreter's `core` path) plus a
 * normalisation through `eval`-path instructions (pv.add.h, pv.dotsp.h, p.clip, p.mulsN), about
 * 10 million instructions on one core. Not a test: run with gap8-run --bench. */
#include "pmsis.h"
#include "xpulp.h"

#define W 64

static uint8_t a[W * W] PI_L1;
static uint8_t b[W * W] PI_L1;

static uint32_t sad8x8(const uint8_t *p, const uint8_t *q) {
  uint32_t s = 0;
  for (int y = 0; y < 8; ++y) {
    const uint32_t *pw = (const uint32_t *)(p + y * W), *qw = (const uint32_t *)(q + y * W);
    for (int x = 0; x < 2; ++x) {
      const uint32_t u = gap8_p_lw_post(&pw), v = gap8_p_lw_post(&qw);
      const uint32_t d = gap8_pv_sub_b(gap8_pv_maxu_b(u, v), gap8_pv_minu_b(u, v));
      s = gap8_pv_sdotup_b(s, d, 0x01010101u);
    }
  }
  const uint32_t pair = GAP8_XPULP_PV_OP(ADD, H, s, s << 16);
  const uint32_t dot = GAP8_XPULP_PV_OP(DOTSP, H, pair, 0x00010001u);
  return GAP8_XPULP_P_CLIP(GAP8_XPULP_P_MULSN(dot, 3, 1), 16);
}

int main(void) {
  for (int i = 0; i < W * W; ++i) {
    a[i] = (uint8_t)(i * 13 + (i >> 6));
    b[i] = (uint8_t)(i * 7 + 1);
  }
  uint32_t best = 0xFFFFFFFFu;
  for (int round = 0; round < 160; ++round) {
    for (int y = 0; y + 8 <= W; y += 2) {
      for (int x = 0; x + 8 <= W; x += 4) {
        const uint32_t s = sad8x8(&a[y * W + x], &b[((y + round) % 56) * W + x]);
        if (s < best) best = s;
      }
    }
  }
  printf("bench_xpulp best %u\n", best);
  return 0;
}
