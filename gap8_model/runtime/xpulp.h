/* Xpulp (PULPv2, GAP8's RI5CY) instructions as C inline functions. Debian's GCC does not know
 * them, so each is emitted with the assembler's .insn directive in its real encoding; the model
 * decodes these encodings. Encodings: funct7 = funct6 << 1 for the packed-SIMD byte forms
 * (opcode 0x57, funct3 1 = vector, 5 = .sc scalar), funct7 2 on OP for p.abs/min/max. */
#ifndef GAP8_XPULP_H
#define GAP8_XPULP_H

#include <stdint.h>

#define GAP8_XPULP_RR(name, f3, f7)                                                            \
  static inline uint32_t name(uint32_t a, uint32_t b) {                                        \
    uint32_t r;                                                                                \
    __asm__ volatile(".insn r 0x57, " #f3 ", " #f7 ", %0, %1, %2" : "=r"(r) : "r"(a), "r"(b)); \
    return r;                                                                                  \
  }

GAP8_XPULP_RR(gap8_pv_add_b, 1, 0x00)
GAP8_XPULP_RR(gap8_pv_add_sc_b, 5, 0x00)
GAP8_XPULP_RR(gap8_pv_sub_b, 1, 0x04)
GAP8_XPULP_RR(gap8_pv_sub_sc_b, 5, 0x04)
GAP8_XPULP_RR(gap8_pv_avgu_b, 1, 0x0C)
GAP8_XPULP_RR(gap8_pv_avgu_sc_b, 5, 0x0C)
GAP8_XPULP_RR(gap8_pv_minu_b, 1, 0x14)
GAP8_XPULP_RR(gap8_pv_minu_sc_b, 5, 0x14)
GAP8_XPULP_RR(gap8_pv_maxu_b, 1, 0x1C)
GAP8_XPULP_RR(gap8_pv_maxu_sc_b, 5, 0x1C)
GAP8_XPULP_RR(gap8_pv_dotup_b, 1, 0x40)
GAP8_XPULP_RR(gap8_pv_dotup_sc_b, 5, 0x40)
GAP8_XPULP_RR(gap8_pv_dotusp_b, 1, 0x44)
GAP8_XPULP_RR(gap8_pv_dotusp_sc_b, 5, 0x44)

/* pv.sdot*: acc + dot product; the accumulator is rd (read and written). */
#define GAP8_XPULP_ACC(name, f3, f7)                                                             \
  static inline uint32_t name(uint32_t acc, uint32_t a, uint32_t b) {                            \
    __asm__ volatile(".insn r 0x57, " #f3 ", " #f7 ", %0, %1, %2" : "+r"(acc) : "r"(a), "r"(b)); \
    return acc;                                                                                  \
  }

GAP8_XPULP_ACC(gap8_pv_sdotup_b, 1, 0x50)
GAP8_XPULP_ACC(gap8_pv_sdotup_sc_b, 5, 0x50)
GAP8_XPULP_ACC(gap8_pv_sdotusp_b, 1, 0x54)
GAP8_XPULP_ACC(gap8_pv_sdotusp_sc_b, 5, 0x54)

static inline uint32_t gap8_pv_abs_b(uint32_t a) {
  uint32_t r;
  __asm__ volatile(".insn r 0x57, 1, 0x38, %0, %1, x0" : "=r"(r) : "r"(a));
  return r;
}

#define GAP8_PULP_ALU(name, f3)                                                             \
  static inline uint32_t name(uint32_t a, uint32_t b) {                                     \
    uint32_t r;                                                                             \
    __asm__ volatile(".insn r 0x33, " #f3 ", 0x02, %0, %1, %2" : "=r"(r) : "r"(a), "r"(b)); \
    return r;                                                                               \
  }

GAP8_PULP_ALU(gap8_p_min, 4)
GAP8_PULP_ALU(gap8_p_minu, 5)
GAP8_PULP_ALU(gap8_p_max, 6)
GAP8_PULP_ALU(gap8_p_maxu, 7)

static inline uint32_t gap8_p_abs(uint32_t a) {
  uint32_t r;
  __asm__ volatile(".insn r 0x33, 0, 0x02, %0, %1, x0" : "=r"(r) : "r"(a));
  return r;
}

/* Post-increment loads: returns **p and advances *p by one element (p.lbu / p.lw rd, imm(rs1!)). */
#define GAP8_LOAD_POST(name, type, f3)                   \
  static inline uint32_t name(const type** p) {          \
    uint32_t r;                                          \
    __asm__ volatile(".insn i 0x0B, " #f3 ", %0, %1, %2" \
                     : "=r"(r), "+r"(*p)                 \
                     : "i"(sizeof(type))                 \
                     : "memory");                        \
    return r;                                            \
  }

GAP8_LOAD_POST(gap8_p_lbu_post, uint8_t, 4)
GAP8_LOAD_POST(gap8_p_lw_post, uint32_t, 2)

/* The same instructions as assembler text, for code that must be a single asm block: the body
 * of a hardware loop, where the compiler must not place code of its own. Operands are strings
 * such as "%[acc]" or "a0"; each macro expands to one instruction and a newline. */
#define GAP8_ASM_PV_SUB_B(rd, a, b) ".insn r 0x57, 1, 0x04, " rd ", " a ", " b "\n\t"
#define GAP8_ASM_PV_MINU_B(rd, a, b) ".insn r 0x57, 1, 0x14, " rd ", " a ", " b "\n\t"
#define GAP8_ASM_PV_MAXU_B(rd, a, b) ".insn r 0x57, 1, 0x1C, " rd ", " a ", " b "\n\t"
#define GAP8_ASM_PV_AVGU_B(rd, a, b) ".insn r 0x57, 1, 0x0C, " rd ", " a ", " b "\n\t"
/* rd = dot(a, b's low byte in every lane) */
#define GAP8_ASM_PV_DOTUP_SC_B(rd, a, b) ".insn r 0x57, 5, 0x40, " rd ", " a ", " b "\n\t"
/* acc += dot(a, b's low byte in every lane) */
#define GAP8_ASM_PV_SDOTUP_SC_B(acc, a, b) ".insn r 0x57, 5, 0x50, " acc ", " a ", " b "\n\t"
/* p.lw rd, imm(rs1!): load the word at rs1, then rs1 += imm (imm a literal, e.g. "4"). */
#define GAP8_ASM_P_LW_POST_IMM(rd, imm, rs1) ".insn i 0x0B, 2, " rd ", " imm "(" rs1 ")\n\t"
/* p.lw rd, rs2(rs1!): load the word at rs1, then rs1 += rs2. */
#define GAP8_ASM_P_LW_POST_REG(rd, rs2, rs1) ".insn r 0x0B, 7, 0x10, " rd ", " rs1 ", " rs2 "\n\t"
/* p.sw rs2, imm(rs1!): store rs2 at rs1, then rs1 += imm (imm a literal). */
#define GAP8_ASM_P_SW_POST_IMM(rs2, imm, rs1) ".insn s 0x2B, 2, " rs2 ", " imm "(" rs1 ")\n\t"
/* p.lw rd, rs2(rs1): load the word at rs1 + rs2. */
#define GAP8_ASM_P_LW_REG(rd, rs2, rs1) ".insn r 0x03, 7, 0x10, " rd ", " rs1 ", " rs2 "\n\t"

/* Brackets for an asm block with hardware loops. RI5CY wants a loop's first instruction word-
 * aligned and no compressed instruction in its body: BEGIN aligns (with the surrounding code's
 * options, so that the linker keeps the alignment) and turns compressed instructions and linker
 * relaxation off, so that every instruction up to END is 4 bytes and hand-counted offsets hold.
 * Whatever follows BEGIN up to a loop's set-up must then be a whole number of words (it is: every
 * instruction is 4 bytes), and the set-up must sit 4 bytes before the body (lp.setup, lp.setupi)
 * or the body start be given to lp.starti. */
#define GAP8_ASM_HWLOOP_BEGIN ".balign 4\n\t.option push\n\t.option norvc\n\t.option norelax\n\t"
#define GAP8_ASM_HWLOOP_END ".option pop"

/* Hardware loops (opcode 0x7B; loop 0 is the inner one and has priority). The end is the
 * address of the loop's LAST instruction, given as an offset in half-words from the set-up
 * instruction; that last instruction must not be a branch or jump. `loop` is 0 or 1, the other
 * arguments literals, e.g. GAP8_ASM_LP_SETUPI("0", "8", "24").
 * lp.setupi L, count, end: count (12 bits) and end (5 bits) immediate; body starts at pc + 4. */
#define GAP8_ASM_LP_SETUPI(loop, count, end) ".insn i 0x7B, 5, x" loop ", x" end ", " count "\n\t"
/* lp.setup L, rs1, end: count from rs1, end (12 bits) immediate; body starts at pc + 4. */
#define GAP8_ASM_LP_SETUP(loop, count_reg, end) \
  ".insn i 0x7B, 4, x" loop ", " count_reg ", " end "\n\t"
/* lp.counti L, count: the count alone (12 bits), for a loop whose start and end are set. */
#define GAP8_ASM_LP_COUNTI(loop, count) ".insn i 0x7B, 3, x" loop ", x0, " count "\n\t"
/* lp.starti L, offset / lp.endi L, offset: start or end address, in half-words from pc. */
#define GAP8_ASM_LP_STARTI(loop, offset) ".insn i 0x7B, 0, x" loop ", x0, " offset "\n\t"
#define GAP8_ASM_LP_ENDI(loop, offset) ".insn i 0x7B, 1, x" loop ", x0, " offset "\n\t"
/* Assembly-time check of a loop's hand-counted end offset (GAS cannot put a label difference
 * into .insn): label `to` must lie `bytes` after label `from`. GAS can only measure code
 * without branches or jumps between the two labels (their size is decided late). */
#define GAP8_ASM_CHECK_DISTANCE(from, to, bytes) \
  ".if (" to " - " from ") != " bytes            \
  "\n\t"                                         \
  ".error \"hand-counted code distance is wrong (hardware loop end)\"\n\t.endif\n\t"

#endif
