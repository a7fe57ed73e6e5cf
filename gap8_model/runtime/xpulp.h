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

#endif
