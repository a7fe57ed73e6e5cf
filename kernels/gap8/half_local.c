/* Variant "local": the paper's second optimisation, recalculations avoided within the 8x8
 * patch, the interpolated values computed during the refinement and kept in the processor's
 * registers ("very few values being put in the stack", the paper's words): half_registers.h,
 * next's words read from next (misaligned loads, as the firmware's word reads). */
#include "flow_kernel.h"
#include "half_registers.h"

const uint32_t variant_planes = 0;

void variant_prepare(const flow_ctx *c, uint32_t core) {
  (void)c;
  (void)core;
}

void variant_half_sads(const flow_ctx *c, const uint8_t *blk, uint32_t mx, uint32_t my,
                       uint32_t sub[8]) {
  const uint8_t *row0 = c->next + (my - 1) * c->width + mx - 1; /* P(-1, -1) */
  const uint8_t *const words[3] = {row0, row0 + 1, row0 + 2};
  half_sads_in_registers(blk, words, c->width, sub);
}
