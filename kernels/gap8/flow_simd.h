/* The 4-byte vocabulary of the PX4FLOW firmware (SPEC §7) in Xpulp instructions. GAP8 has no
 * USAD8: one 4-byte SAD is four instructions (the paper's "4 cycles instead of 1"). */
#ifndef PXFLOW_GAP8_FLOW_SIMD_H
#define PXFLOW_GAP8_FLOW_SIMD_H

#include <stdint.h>

#include "xpulp.h"

/* Four bytes from any address: RI5CY splits a misaligned lw in two accesses by itself, as the
 * firmware's *(uint32_t *)&image[...] does on the Cortex-M4. GCC would emit four lbu for a
 * memcpy on this strict-alignment target, hence the one-instruction asm. */
static inline uint32_t ld4(const uint8_t *p) {
  uint32_t v;
  __asm__("lw %0, %1" : "=r"(v) : "m"(*(const uint32_t *)p));
  return v;
}

/* Four bytes to any address (the global planes' rows need not be word aligned). */
static inline void st4(uint8_t *p, uint32_t v) {
  __asm__("sw %1, %0" : "=m"(*(uint32_t *)p) : "r"(v));
}

/* acc + USAD8(a, b): |a - b| per byte as maxu - minu, then a dot product with ones. */
static inline uint32_t sad4_acc(uint32_t acc, uint32_t a, uint32_t b) {
  const uint32_t diff = gap8_pv_sub_b(gap8_pv_maxu_b(a, b), gap8_pv_minu_b(a, b));
  return gap8_pv_sdotup_sc_b(acc, diff, 1u);
}

/* sad4_acc as assembler text, for asm blocks: acc += USAD8(a, b) with t and u as scratch (u may
 * be b itself when b is not needed afterwards); `one` holds 1. Operands are strings ("%[t]"). */
#define SAD4_ACC_ASM(acc, a, b, t, u, one) \
  GAP8_ASM_PV_MAXU_B(t, a, b)              \
  GAP8_ASM_PV_MINU_B(u, a, b)              \
  GAP8_ASM_PV_SUB_B(t, t, u)               \
  GAP8_ASM_PV_SDOTUP_SC_B(acc, t, one)

/* p.minu rd, rs1, rs2 (unsigned minimum; opcode 0x33, funct3 5, funct7 2, as xpulp.h's
 * gap8_p_minu), as assembler text. */
#define P_MINU_ASM(rd, a, b) ".insn r 0x33, 5, 0x02, " rd ", " a ", " b "\n\t"

/* The eight half-pixel accumulators of an asm block: operands %[acc0]..%[acc7] written straight
 * to sub[0..7], and the text that clears them. */
#define HALF_ACC_OPERANDS(sub)                                                            \
  [acc0] "=&r"(sub[0]), [acc1] "=&r"(sub[1]), [acc2] "=&r"(sub[2]), [acc3] "=&r"(sub[3]), \
      [acc4] "=&r"(sub[4]), [acc5] "=&r"(sub[5]), [acc6] "=&r"(sub[6]), [acc7] "=&r"(sub[7])
#define HALF_ACC_CLEAR_ASM                                               \
  "li %[acc0], 0\n\tli %[acc1], 0\n\tli %[acc2], 0\n\tli %[acc3], 0\n\t" \
  "li %[acc4], 0\n\tli %[acc5], 0\n\tli %[acc6], 0\n\tli %[acc7], 0\n\t"

/* The shape of the half-pixel step as asm text (half_original.c, half_planes.h): the eight
 * accumulators cleared, then hardware loop 0 over the 8 block rows, whose body is `first` then
 * `second` (the row's two 4-pixel groups). The body starts 12 bytes after lp.starti; `endi` is
 * its last instruction's offset from lp.endi in half-words (a literal), checked at assembly. */
/* clang-format off */
#define HALF_ROWS_ASM(first, second, endi)                                      \
  GAP8_ASM_HWLOOP_BEGIN HALF_ACC_CLEAR_ASM                                      \
  ".Lstart%=: " GAP8_ASM_LP_STARTI("0", "6") GAP8_ASM_LP_ENDI("0", endi)        \
  GAP8_ASM_LP_COUNTI("0", "8") ".Lbody%=: " first second ".Lafter%=:\n\t"       \
  GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lbody%=", "12")                        \
  GAP8_ASM_CHECK_DISTANCE(".Lstart%=", ".Lafter%=", "2 * " endi " + 8")         \
  GAP8_ASM_HWLOOP_END
/* clang-format on */

/* UHADD8, SPEC §7: per byte floor((a + b) / 2), 9-bit intermediate. RI5CY's pv.avgu.b is NOT
 * this: it adds in the 8-bit lane and drops the carry, (uint8)(a_i + b_i) >> 1 (GVSOC gvsoc-core
 * isa_lib/int.h VEC_EXPR(AVGU, ...); GreenWaves' builtins.h; pulp-platform/riscv-tests pv_avgu),
 * wrong whenever a_i + b_i > 255. The floor average is built from the carry-free identity
 *   floor((a + b) / 2) = (a & b) + ((a ^ b) >> 1)   per byte,
 * where the per-byte shift is pv.avgu.sc.b with the scalar 0 (x0): (uint8)(t_i + 0) >> 1 =
 * t_i >> 1, no carry possible (GVSOC VEC_EXPR_SC(AVGU, uint32_t, uint8_t, ...,
 * ((uint8_t)(tmp_a[i] + b) >> 1)), b the scalar's low byte). Four one-cycle instructions: and,
 * xor, pv.avgu.sc.b, add (plain RV32 would need srli and an and with 0x7F7F7F7F instead of the
 * pv.avgu.sc.b: five). */
static inline uint32_t avg4(uint32_t a, uint32_t b) {
  return (a & b) + gap8_pv_avgu_sc_b(a ^ b, 0u);
}

/* pv.avgu.sc.b rd, rs1, x0: rd = rs1 >> 1 in each byte (see avg4). */
#define PV_SRL1_B_ASM(rd, rs1) ".insn r 0x57, 5, 0x0C, " rd ", " rs1 ", x0\n\t"

/* avg4 as assembler text: d = floor((a + b) / 2) per byte, t scratch; d may be a or b (t must be
 * neither). The and reads both inputs first, so a load of a or b two instructions earlier does
 * not stall. */
#define FLOOR_AVG_ASM(d, a, b, t) \
  "and " t ", " a ", " b          \
  "\n\t"                          \
  "xor " d ", " a ", " b "\n\t" PV_SRL1_B_ASM(d, d) "add " d ", " d ", " t "\n\t"

/* The primitives of the shared per-POI kernel (pxflow_spec/poi_kernel.h). */
#define PXFLOW_POI_LD4(p) ld4(p)
#define PXFLOW_POI_SAD4_ACC(acc, a, b) sad4_acc(acc, a, b)
#define PXFLOW_POI_AVG4(a, b) avg4(a, b)

#endif
