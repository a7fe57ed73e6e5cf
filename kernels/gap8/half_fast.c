/* The fast variant's half-pixel step (beyond the paper): the local optimisation in registers
 * (half_registers.h), next's words read aligned from the shifted copies of next when the fast
 * tables exist (fast_tables.h), else from next itself (misaligned loads, any width). */
#include "fast_tables.h"
#include "half_registers.h"

void variant_half_sads(const flow_ctx *c, const uint8_t *blk, uint32_t mx, uint32_t my,
                       uint32_t sub[8]) {
  /* W a multiple of 4 on the copies' path: each word's copy is the same on every row. */
  const uint32_t o = (my - 1) * c->width + mx - 1;
  const uint8_t *row0[3];
  for (uint32_t e = 0; e < 3; ++e) {
    const uint32_t q = (o + e) & 3;
    row0[e] = g_fast.ready ? g_fast.copy[q] + (o + e - q) : c->next + o + e;
  }
  half_sads_in_registers(blk, row0, c->width, sub);
}
