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

/* ---- The rest of PULPv2 (GAP8's cluster ISA as GVSOC runs it), as GAP8_XPULP_* macros ----
 * Each expands to one instruction in its PULPv2 encoding (gvsoc-core isa_pulpv2.py) and yields
 * its result; the semantics are in gap8_model/include/gap8/xpulp.h with their sources.
 * Names follow the mnemonics: GAP8_XPULP_PV_ADD_H = pv.add.h, ..._SC_H = pv.add.sc.h,
 * ..._SCI_H(a, imm) = pv.add.sci.h. Immediates must be integer constant expressions. */

/* rd = op(rs1, rs2): opcode, funct3, funct7. */
#define GAP8_XPULP_R(opc, f3, f7, a, b)                               \
  ({                                                                  \
    uint32_t r_;                                                      \
    __asm__ volatile(".insn r " #opc ", " #f3 ", " #f7 ", %0, %1, %2" \
                     : "=r"(r_)                                       \
                     : "r"((uint32_t)(a)), "r"((uint32_t)(b)));       \
    r_;                                                               \
  })
/* rd = op(rs1), rs2 field x0. */
#define GAP8_XPULP_R1(opc, f3, f7, a)                                 \
  ({                                                                  \
    uint32_t r_;                                                      \
    __asm__ volatile(".insn r " #opc ", " #f3 ", " #f7 ", %0, %1, x0" \
                     : "=r"(r_)                                       \
                     : "r"((uint32_t)(a)));                           \
    r_;                                                               \
  })
/* rd = op(rd, rs1, rs2): the instruction reads and writes rd. */
#define GAP8_XPULP_RACC(opc, f3, f7, acc, a, b)                       \
  ({                                                                  \
    uint32_t r_ = (uint32_t)(acc);                                    \
    __asm__ volatile(".insn r " #opc ", " #f3 ", " #f7 ", %0, %1, %2" \
                     : "+r"(r_)                                       \
                     : "r"((uint32_t)(a)), "r"((uint32_t)(b)));       \
    r_;                                                               \
  })
/* An I-type view of an encoding whose bits 31..20 are `imm12` (sign-folded for .insn i). */
#define GAP8_XPULP_IMM12(imm12) ((((int)(imm12)) ^ 0x800) - 0x800)
#define GAP8_XPULP_I(opc, f3, imm12, a)                                   \
  ({                                                                      \
    uint32_t r_;                                                          \
    __asm__ volatile(".insn i " #opc ", " #f3 ", %0, %1, %2"              \
                     : "=r"(r_)                                           \
                     : "r"((uint32_t)(a)), "i"(GAP8_XPULP_IMM12(imm12))); \
    r_;                                                                   \
  })
#define GAP8_XPULP_IACC(opc, f3, imm12, acc, a)                           \
  ({                                                                      \
    uint32_t r_ = (uint32_t)(acc);                                        \
    __asm__ volatile(".insn i " #opc ", " #f3 ", %0, %1, %2"              \
                     : "+r"(r_)                                           \
                     : "r"((uint32_t)(a)), "i"(GAP8_XPULP_IMM12(imm12))); \
    r_;                                                                   \
  })
/* Packed SIMD (opcode 0x57): funct6, funct3 0 .h, 1 .b, 4 .sc.h, 5 .sc.b, 6 .sci.h, 7 .sci.b;
 * the 6-bit .sci immediate goes to bit 25 (imm[0]) and bits 24..20 (imm[5:1]). */
#define GAP8_XPULP_SCI12(f6, imm) (((f6) << 6) | (((imm)&1) << 5) | (((imm) >> 1) & 31))
#define GAP8_XPULP_PV(f6, f3, a, b) GAP8_XPULP_R(0x57, f3, ((f6) << 1), a, b)
#define GAP8_XPULP_PV_ACC(f6, f3, acc, a, b) GAP8_XPULP_RACC(0x57, f3, ((f6) << 1), acc, a, b)
#define GAP8_XPULP_PV_SCI(f6, f3, a, imm) GAP8_XPULP_I(0x57, f3, GAP8_XPULP_SCI12(f6, imm), a)
#define GAP8_XPULP_PV_SCI_ACC(f6, f3, acc, a, imm) \
  GAP8_XPULP_IACC(0x57, f3, GAP8_XPULP_SCI12(f6, imm), acc, a)

/* pv.<op>{.h,.b,.sc.h,.sc.b}: GAP8_XPULP_PV_<OP>_<FORM>(a, b); .sci: GAP8_XPULP_PV_<OP>_SCI_H
 * / _SCI_B(a, imm). funct6 from GVSOC's table. */
#define GAP8_XPULP_F6_ADD 0x00
#define GAP8_XPULP_F6_SUB 0x02
#define GAP8_XPULP_F6_AVG 0x04
#define GAP8_XPULP_F6_AVGU 0x06
#define GAP8_XPULP_F6_MIN 0x08
#define GAP8_XPULP_F6_MINU 0x0A
#define GAP8_XPULP_F6_MAX 0x0C
#define GAP8_XPULP_F6_MAXU 0x0E
#define GAP8_XPULP_F6_SRL 0x10
#define GAP8_XPULP_F6_SRA 0x12
#define GAP8_XPULP_F6_SLL 0x14
#define GAP8_XPULP_F6_OR 0x16
#define GAP8_XPULP_F6_XOR 0x18
#define GAP8_XPULP_F6_AND 0x1A
#define GAP8_XPULP_F6_DOTUP 0x20
#define GAP8_XPULP_F6_DOTUSP 0x22
#define GAP8_XPULP_F6_DOTSP 0x26
#define GAP8_XPULP_F6_SDOTUP 0x28
#define GAP8_XPULP_F6_SDOTUSP 0x2A
#define GAP8_XPULP_F6_SDOTSP 0x2E
#define GAP8_XPULP_F6_CMPEQ 0x01
#define GAP8_XPULP_F6_CMPNE 0x03
#define GAP8_XPULP_F6_CMPGT 0x05
#define GAP8_XPULP_F6_CMPGE 0x07
#define GAP8_XPULP_F6_CMPLT 0x09
#define GAP8_XPULP_F6_CMPLE 0x0B
#define GAP8_XPULP_F6_CMPGTU 0x0D
#define GAP8_XPULP_F6_CMPGEU 0x0F
#define GAP8_XPULP_F6_CMPLTU 0x11
#define GAP8_XPULP_F6_CMPLEU 0x13
/* GAP8_XPULP_PV_OP(ADD, H, a, b) = pv.add.h; (ADD, SC_B, a, b) = pv.add.sc.b. */
#define GAP8_XPULP_FORM_H 0
#define GAP8_XPULP_FORM_B 1
#define GAP8_XPULP_FORM_SC_H 4
#define GAP8_XPULP_FORM_SC_B 5
#define GAP8_XPULP_FORM_SCI_H 6
#define GAP8_XPULP_FORM_SCI_B 7
#define GAP8_XPULP_PV_OP(OP, FORM, a, b) \
  GAP8_XPULP_PV(GAP8_XPULP_F6_##OP, GAP8_XPULP_FORM_##FORM, a, b)
#define GAP8_XPULP_PV_OP_SCI(OP, FORM, a, imm) \
  GAP8_XPULP_PV_SCI(GAP8_XPULP_F6_##OP, GAP8_XPULP_FORM_##FORM, a, imm)
/* pv.sdot*: acc + dot product, the accumulator in rd. */
#define GAP8_XPULP_PV_SDOT(OP, FORM, acc, a, b) \
  GAP8_XPULP_PV_ACC(GAP8_XPULP_F6_##OP, GAP8_XPULP_FORM_##FORM, acc, a, b)
#define GAP8_XPULP_PV_SDOT_SCI(OP, FORM, acc, a, imm) \
  GAP8_XPULP_PV_SCI_ACC(GAP8_XPULP_F6_##OP, GAP8_XPULP_FORM_##FORM, acc, a, imm)

#define GAP8_XPULP_PV_ABS_H(a) GAP8_XPULP_R1(0x57, 0, 0x38, a)
#define GAP8_XPULP_PV_EXTRACT_H(a, i) GAP8_XPULP_PV_SCI(0x1E, 6, a, i)
#define GAP8_XPULP_PV_EXTRACT_B(a, i) GAP8_XPULP_PV_SCI(0x1E, 7, a, i)
#define GAP8_XPULP_PV_EXTRACTU_H(a, i) GAP8_XPULP_PV_SCI(0x24, 6, a, i)
#define GAP8_XPULP_PV_EXTRACTU_B(a, i) GAP8_XPULP_PV_SCI(0x24, 7, a, i)
#define GAP8_XPULP_PV_INSERT_H(rd, a, i) GAP8_XPULP_PV_SCI_ACC(0x2C, 6, rd, a, i)
#define GAP8_XPULP_PV_INSERT_B(rd, a, i) GAP8_XPULP_PV_SCI_ACC(0x2C, 7, rd, a, i)
#define GAP8_XPULP_PV_SHUFFLE_H(a, sel) GAP8_XPULP_PV(0x30, 0, a, sel)
#define GAP8_XPULP_PV_SHUFFLE_B(a, sel) GAP8_XPULP_PV(0x30, 1, a, sel)
#define GAP8_XPULP_PV_SHUFFLE_SCI_H(a, imm) GAP8_XPULP_PV_SCI(0x30, 6, a, imm)
#define GAP8_XPULP_PV_SHUFFLEI0_SCI_B(a, imm) GAP8_XPULP_PV_SCI(0x30, 7, a, imm)
#define GAP8_XPULP_PV_SHUFFLEI1_SCI_B(a, imm) GAP8_XPULP_PV_SCI(0x3A, 7, a, imm)
#define GAP8_XPULP_PV_SHUFFLEI2_SCI_B(a, imm) GAP8_XPULP_PV_SCI(0x3C, 7, a, imm)
#define GAP8_XPULP_PV_SHUFFLEI3_SCI_B(a, imm) GAP8_XPULP_PV_SCI(0x3E, 7, a, imm)
#define GAP8_XPULP_PV_SHUFFLE2_H(rd, a, sel) GAP8_XPULP_PV_ACC(0x32, 0, rd, a, sel)
#define GAP8_XPULP_PV_SHUFFLE2_B(rd, a, sel) GAP8_XPULP_PV_ACC(0x32, 1, rd, a, sel)
#define GAP8_XPULP_PV_PACK_H(a, b) GAP8_XPULP_PV(0x34, 0, a, b)
#define GAP8_XPULP_PV_PACKHI_B(rd, a, b) GAP8_XPULP_PV_ACC(0x36, 1, rd, a, b)
#define GAP8_XPULP_PV_PACKLO_B(rd, a, b) GAP8_XPULP_PV_ACC(0x38, 1, rd, a, b)

/* GAP8's own SIMD extensions (gap_sdk GVSOC, ISA subset `gap8`): complex values im:re. */
#define GAP8_XPULP_PV_ADD_H_DIV2(a, b) GAP8_XPULP_R(0x57, 2, 0x00, a, b)
#define GAP8_XPULP_PV_ADD_H_DIV4(a, b) GAP8_XPULP_R(0x57, 2, 0x01, a, b)
#define GAP8_XPULP_PV_ADD_B_DIV2(a, b) GAP8_XPULP_R(0x57, 3, 0x00, a, b)
#define GAP8_XPULP_PV_ADD_B_DIV4(a, b) GAP8_XPULP_R(0x57, 3, 0x01, a, b)
#define GAP8_XPULP_PV_SUB_H_DIV2(a, b) GAP8_XPULP_R(0x57, 2, 0x04, a, b)
#define GAP8_XPULP_PV_SUB_H_DIV4(a, b) GAP8_XPULP_R(0x57, 2, 0x05, a, b)
#define GAP8_XPULP_PV_SUB_B_DIV2(a, b) GAP8_XPULP_R(0x57, 3, 0x04, a, b)
#define GAP8_XPULP_PV_SUB_B_DIV4(a, b) GAP8_XPULP_R(0x57, 3, 0x05, a, b)
#define GAP8_XPULP_PV_CPLXMUL_S(a, b) GAP8_XPULP_R(0x57, 0, 0x2A, a, b)
#define GAP8_XPULP_PV_CPLXMUL_S_DIV2(a, b) GAP8_XPULP_R(0x57, 2, 0x2A, a, b)
#define GAP8_XPULP_PV_CPLXMUL_S_DIV4(a, b) GAP8_XPULP_R(0x57, 2, 0x2B, a, b)
#define GAP8_XPULP_PV_CPLXCONJ_H(a) GAP8_XPULP_R1(0x57, 0, 0x2E, a)
#define GAP8_XPULP_PV_SUBROTMJ_H(a, b) GAP8_XPULP_R(0x57, 0, 0x36, a, b)
#define GAP8_XPULP_PV_SUBROTMJ_H_DIV2(a, b) GAP8_XPULP_R(0x57, 2, 0x36, a, b)
#define GAP8_XPULP_PV_SUBROTMJ_H_DIV4(a, b) GAP8_XPULP_R(0x57, 2, 0x37, a, b)
#define GAP8_XPULP_PV_PACK_H_H(a, b) GAP8_XPULP_R(0x57, 6, 0x68, a, b)
#define GAP8_XPULP_PV_PACK_L_H(a, b) GAP8_XPULP_R(0x57, 4, 0x68, a, b)

/* Scalar ALU (opcode 0x33): funct7 0000010, 0000100, 0001000, 0001010, 0100001, 1000000. */
#define GAP8_XPULP_P_AVGU(a, b) GAP8_XPULP_R(0x33, 1, 0x02, a, b)
#define GAP8_XPULP_P_SLET(a, b) GAP8_XPULP_R(0x33, 2, 0x02, a, b)
#define GAP8_XPULP_P_SLETU(a, b) GAP8_XPULP_R(0x33, 3, 0x02, a, b)
#define GAP8_XPULP_P_ROR(a, b) GAP8_XPULP_R(0x33, 5, 0x04, a, b)
#define GAP8_XPULP_P_FF1(a) GAP8_XPULP_R1(0x33, 0, 0x08, a)
#define GAP8_XPULP_P_FL1(a) GAP8_XPULP_R1(0x33, 1, 0x08, a)
#define GAP8_XPULP_P_CLB(a) GAP8_XPULP_R1(0x33, 2, 0x08, a)
#define GAP8_XPULP_P_CNT(a) GAP8_XPULP_R1(0x33, 3, 0x08, a)
#define GAP8_XPULP_P_EXTHS(a) GAP8_XPULP_R1(0x33, 4, 0x08, a)
#define GAP8_XPULP_P_EXTHZ(a) GAP8_XPULP_R1(0x33, 5, 0x08, a)
#define GAP8_XPULP_P_EXTBS(a) GAP8_XPULP_R1(0x33, 6, 0x08, a)
#define GAP8_XPULP_P_EXTBZ(a) GAP8_XPULP_R1(0x33, 7, 0x08, a)
/* p.clip / p.clipu rD, rs1, Is2: Is2 in the rs2 field. */
#define GAP8_XPULP_P_CLIP(a, is2) GAP8_XPULP_I(0x33, 1, ((0x0A << 5) | ((is2)&31)), a)
#define GAP8_XPULP_P_CLIPU(a, is2) GAP8_XPULP_I(0x33, 2, ((0x0A << 5) | ((is2)&31)), a)
#define GAP8_XPULP_P_CLIPR(a, b) GAP8_XPULP_R(0x33, 5, 0x0A, a, b)
#define GAP8_XPULP_P_CLIPUR(a, b) GAP8_XPULP_R(0x33, 6, 0x0A, a, b)
#define GAP8_XPULP_P_MAC(acc, a, b) GAP8_XPULP_RACC(0x33, 0, 0x21, acc, a, b)
#define GAP8_XPULP_P_MSU(acc, a, b) GAP8_XPULP_RACC(0x33, 1, 0x21, acc, a, b)
/* Bit fields, immediate forms: Is3 = width - 1 (bits 29..25), Is2 = position (24..20). */
#define GAP8_XPULP_BITFIELD12(is3, is2) ((3 << 10) | (((is3)&31) << 5) | ((is2)&31))
#define GAP8_XPULP_P_EXTRACT(a, is3, is2) GAP8_XPULP_I(0x33, 0, GAP8_XPULP_BITFIELD12(is3, is2), a)
#define GAP8_XPULP_P_EXTRACTU(a, is3, is2) GAP8_XPULP_I(0x33, 1, GAP8_XPULP_BITFIELD12(is3, is2), a)
#define GAP8_XPULP_P_INSERT(rd, a, is3, is2) \
  GAP8_XPULP_IACC(0x33, 2, GAP8_XPULP_BITFIELD12(is3, is2), rd, a)
#define GAP8_XPULP_P_BCLR(a, is3, is2) GAP8_XPULP_I(0x33, 3, GAP8_XPULP_BITFIELD12(is3, is2), a)
#define GAP8_XPULP_P_BSET(a, is3, is2) GAP8_XPULP_I(0x33, 4, GAP8_XPULP_BITFIELD12(is3, is2), a)
/* Register forms: rs2 = (width - 1) << 5 | position. */
#define GAP8_XPULP_P_EXTRACTR(a, f) GAP8_XPULP_R(0x33, 0, 0x40, a, f)
#define GAP8_XPULP_P_EXTRACTUR(a, f) GAP8_XPULP_R(0x33, 1, 0x40, a, f)
#define GAP8_XPULP_P_INSERTR(rd, a, f) GAP8_XPULP_RACC(0x33, 2, 0x40, rd, a, f)
#define GAP8_XPULP_P_BCLRR(a, f) GAP8_XPULP_R(0x33, 3, 0x40, a, f)
#define GAP8_XPULP_P_BSETR(a, f) GAP8_XPULP_R(0x33, 4, 0x40, a, f)

/* 16-bit multiplies and MACs, normalised add/sub (opcode 0x5B): funct7 = variant << 5 | Is3
 * with variant 0 u, 1 hhu, 2 s, 3 hhs (multiplies) or 0 N, 2 uN (add/sub); funct3 0 mul,
 * 4 mul R, 1 mac, 5 mac R, 2 add, 6 add R, 3 sub, 7 sub R. */
#define GAP8_XPULP_MUL16(f3, variant, is3, a, b) \
  GAP8_XPULP_R(0x5B, f3, (((variant) << 5) | ((is3)&31)), a, b)
#define GAP8_XPULP_MAC16(f3, variant, is3, acc, a, b) \
  GAP8_XPULP_RACC(0x5B, f3, (((variant) << 5) | ((is3)&31)), acc, a, b)
#define GAP8_XPULP_P_MULS(a, b) GAP8_XPULP_MUL16(0, 2, 0, a, b)
#define GAP8_XPULP_P_MULHHS(a, b) GAP8_XPULP_MUL16(0, 3, 0, a, b)
#define GAP8_XPULP_P_MULU(a, b) GAP8_XPULP_MUL16(0, 0, 0, a, b)
#define GAP8_XPULP_P_MULHHU(a, b) GAP8_XPULP_MUL16(0, 1, 0, a, b)
#define GAP8_XPULP_P_MULSN(a, b, n) GAP8_XPULP_MUL16(0, 2, n, a, b)
#define GAP8_XPULP_P_MULSRN(a, b, n) GAP8_XPULP_MUL16(4, 2, n, a, b)
#define GAP8_XPULP_P_MULHHURN(a, b, n) GAP8_XPULP_MUL16(4, 1, n, a, b)
#define GAP8_XPULP_P_MACS(acc, a, b) GAP8_XPULP_MAC16(1, 2, 0, acc, a, b)
#define GAP8_XPULP_P_MACHHU(acc, a, b) GAP8_XPULP_MAC16(1, 1, 0, acc, a, b)
#define GAP8_XPULP_P_MACSRN(acc, a, b, n) GAP8_XPULP_MAC16(5, 2, n, acc, a, b)
#define GAP8_XPULP_P_MACUN(acc, a, b, n) GAP8_XPULP_MAC16(1, 0, n, acc, a, b)
#define GAP8_XPULP_P_ADDN(a, b, n) GAP8_XPULP_MUL16(2, 0, n, a, b)
#define GAP8_XPULP_P_ADDUN(a, b, n) GAP8_XPULP_MUL16(2, 2, n, a, b)
#define GAP8_XPULP_P_ADDRN(a, b, n) GAP8_XPULP_MUL16(6, 0, n, a, b)
#define GAP8_XPULP_P_SUBN(a, b, n) GAP8_XPULP_MUL16(3, 0, n, a, b)
#define GAP8_XPULP_P_SUBURN(a, b, n) GAP8_XPULP_MUL16(7, 2, n, a, b)
/* Register forms: rD = (rD +/- rs1 [+ round]) >> rs2[4:0] (variant 1 signed, 3 unsigned). */
#define GAP8_XPULP_P_ADDNR(rd, a, shift) GAP8_XPULP_MAC16(2, 1, 0, rd, a, shift)
#define GAP8_XPULP_P_SUBURNR(rd, a, shift) GAP8_XPULP_MAC16(7, 3, 0, rd, a, shift)

/* Loads and stores of every width (p.lb, p.lbu, p.lh, p.lhu, p.lw = widths 0, 4, 1, 5, 2):
 * rd, imm(rs1!) post-increment; rd, rs2(rs1!) register post-increment; rd, rs2(rs1) register
 * offset (funct7 encodes the width: 0x00 lb, 0x20 lbu, 0x08 lh, 0x28 lhu, 0x10 lw). */
#define GAP8_XPULP_LOAD_POST_IMM(width, p, imm)             \
  ({                                                        \
    uint32_t r_;                                            \
    __asm__ volatile(".insn i 0x0B, " #width ", %0, %2(%1)" \
                     : "=r"(r_), "+r"(p)                    \
                     : "i"(imm)                             \
                     : "memory");                           \
    r_;                                                     \
  })
#define GAP8_XPULP_LOAD_POST_REG(f7, p, step)               \
  ({                                                        \
    uint32_t r_;                                            \
    __asm__ volatile(".insn r 0x0B, 7, " #f7 ", %0, %1, %2" \
                     : "=r"(r_), "+r"(p)                    \
                     : "r"(step)                            \
                     : "memory");                           \
    r_;                                                     \
  })
#define GAP8_XPULP_LOAD_REG(f7, p, offset)                  \
  ({                                                        \
    uint32_t r_;                                            \
    __asm__ volatile(".insn r 0x03, 7, " #f7 ", %0, %1, %2" \
                     : "=r"(r_)                             \
                     : "r"(p), "r"(offset)                  \
                     : "memory");                           \
    r_;                                                     \
  })
/* p.sb/p.sh/p.sw (widths 0, 1, 2): value, imm(rs1!) / rs3(rs1!) / rs3(rs1). */
#define GAP8_XPULP_STORE_POST_IMM(width, value, p, imm)   \
  __asm__ volatile(".insn s 0x2B, " #width ", %1, %2(%0)" \
                   : "+r"(p)                              \
                   : "r"(value), "i"(imm)                 \
                   : "memory")
#define GAP8_XPULP_STORE_POST_REG(width, value, p, step)         \
  __asm__ volatile(".insn r 0x2B, " #width " + 4, 0, %2, %0, %1" \
                   : "+r"(p)                                     \
                   : "r"(value), "r"(step)                       \
                   : "memory")
#define GAP8_XPULP_STORE_REG(width, value, p, offset)            \
  __asm__ volatile(".insn r 0x23, " #width " + 4, 0, %2, %0, %1" \
                   :                                             \
                   : "r"(p), "r"(value), "r"(offset)             \
                   : "memory")

/* p.beqimm / p.bneimm are branches: use them in asm blocks, as text; imm5 is the immediate's
 * 5-bit pattern as a literal 0..31 (31 = -1), it sits in the rs2 field. */
#define GAP8_ASM_P_BEQIMM(rs1, imm5, label) ".insn sb 0x63, 2, " rs1 ", x" imm5 ", " label "\n\t"
#define GAP8_ASM_P_BNEIMM(rs1, imm5, label) ".insn sb 0x63, 3, " rs1 ", x" imm5 ", " label "\n\t"

/* The same instructions as assembler text, for code that must be a single asm block: the body
 * of a hardware loop, where the compiler must not place code of its own. Operands are strings
 * such as "%[acc]" or "a0"; each macro expands to one instruction and a newline. */
#define GAP8_ASM_PV_SUB_B(rd, a, b) ".insn r 0x57, 1, 0x04, " rd ", " a ", " b "\n\t"
#define GAP8_ASM_PV_MINU_B(rd, a, b) ".insn r 0x57, 1, 0x14, " rd ", " a ", " b "\n\t"
#define GAP8_ASM_PV_MAXU_B(rd, a, b) ".insn r 0x57, 1, 0x1C, " rd ", " a ", " b "\n\t"
#define GAP8_ASM_PV_AVGU_B(rd, a, b) ".insn r 0x57, 1, 0x0C, " rd ", " a ", " b "\n\t"
/* Any packed-SIMD instruction as text: funct6 and funct3 as literals (see GAP8_XPULP_F6_* and
 * GAP8_XPULP_FORM_*), e.g. GAP8_ASM_PV("0x00", "1", "%[r]", "%[a]", "%[b]") = pv.add.b; the
 * .sci form takes the 6-bit immediate as a literal, folded into the I-type immediate by the
 * assembler, e.g. GAP8_ASM_PV_SCI("0x10", "7", "%[r]", "%[a]", "1") = pv.srl.sci.b r, a, 1. */
#define GAP8_ASM_PV(f6, f3, rd, a, b) \
  ".insn r 0x57, " f3 ", (" f6 ") << 1, " rd ", " a ", " b "\n\t"
/* (GAS gives | & ^ one precedence, below << and >>: every term is parenthesised.) */
#define GAP8_ASM_PV_SCI(f6, f3, rd, a, imm)                                                    \
  ".insn i 0x57, " f3 ", " rd ", " a ", (((((" f6 ") << 6) | (((" imm ") & 1) << 5) | (((" imm \
  ") >> 1) & 31)) ^ 0x800) - 0x800)\n\t"
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
