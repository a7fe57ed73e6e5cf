/* The .insn wrappers of xpulp.h against plain C: checks the encodings they emit decode, in the
 * model, to the intended operations (the model's semantics are unit-tested on the host). */
#include "pmsis.h"
#include "xpulp.h"

static uint32_t lane(uint32_t x, int i) { return (x >> (8 * i)) & 0xFF; }

static uint32_t sad_c(uint32_t a, uint32_t b) {
  uint32_t s = 0;
  for (int i = 0; i < 4; ++i)
    s += lane(a, i) > lane(b, i) ? lane(a, i) - lane(b, i) : lane(b, i) - lane(a, i);
  return s;
}

static const uint8_t bytes[8] __attribute__((aligned(4))) = {1, 2, 3, 250, 9, 8, 7, 6};

int main(void) {
  const uint32_t a = 0x80FF1203u, b = 0x7F01F004u;
  if (gap8_pv_maxu_b(a, b) != 0x80FFF004u) return 1;
  if (gap8_pv_minu_b(a, b) != 0x7F011203u) return 2;
  if (gap8_pv_sub_b(a, b) != 0x01FE22FFu) return 3;
  if (gap8_pv_avgu_b(a, b) != 0x7F000103u) return 4; /* lane carry lost (RI5CY) */
  /* |a - b| per byte = maxu - minu; the SAD = its dot product with 1s. */
  const uint32_t diff = gap8_pv_sub_b(gap8_pv_maxu_b(a, b), gap8_pv_minu_b(a, b));
  if (gap8_pv_sdotup_sc_b(10, diff, 1) != 10 + sad_c(a, b)) return 5;
  if (gap8_pv_sdotup_b(0, 0x01020304u, 0x05060708u) != 5 * 1 + 6 * 2 + 7 * 3 + 8 * 4) return 6;
  if (gap8_pv_sdotusp_b(0, 0x000000FFu, 0x000000FFu) != (uint32_t)(255 * -1)) return 7;
  if (gap8_pv_dotup_sc_b(0x01010101u, 3) != 12) return 8;
  if (gap8_p_abs((uint32_t)-42) != 42) return 9;
  if (gap8_p_min((uint32_t)-3, 2) != (uint32_t)-3 || gap8_p_minu((uint32_t)-3, 2) != 2) return 10;
  if (gap8_p_max((uint32_t)-3, 2) != 2 || gap8_p_maxu((uint32_t)-3, 2) != (uint32_t)-3) return 11;
  if (gap8_pv_abs_b(0xFF80017Fu) != 0x0180017Fu) return 12;
  if (gap8_pv_add_sc_b(0x01020304u, 0x10) != 0x11121314u) return 13;
  const uint8_t *p = bytes;
  uint32_t sum = 0;
  for (int i = 0; i < 8; ++i) sum += gap8_p_lbu_post(&p);
  if (sum != 286 || p != bytes + 8) return 14;
  const uint32_t *w = (const uint32_t *)bytes;
  if (gap8_p_lw_post(&w) != 0xFA030201u || w != (const uint32_t *)bytes + 1) return 15;
  printf("xpulp ok\n");
  return 0;
}
