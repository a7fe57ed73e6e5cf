/* Xpulp (PULPv2, GAP8's RI5CY) instructions as C inline functions. Debian's GCC does not know
 * them, so each is emitted with the assembler's .insn directive in its real encoding; the model
 * decodes these encodings. The encodings are not written here: xpulp_fields.h, generated at
 * build time from gap8_model/isa/xpulp.tbl, gives each instruction's GAP8_XPULP_OPC_<M>,
 * GAP8_XPULP_F3_<M> and GAP8_XPULP_F7_<M> (M = the mnemonic in capitals, dots as _). */
#ifndef GAP8_XPULP_H
#define GAP8_XPULP_H

#include <stdint.h>

#include "xpulp_fields.h"

/* A macro's value as a string, for .insn (the value, not the macro's name). */
#define GAP8_STR_(x) #x
#define GAP8_STR(x) GAP8_STR_(x)
/* ".insn r OPC, F3, F7, " of instruction M, as assembler text. */
#define GAP8_INSN_R(M)                                                                    \
  ".insn r " GAP8_STR(GAP8_XPULP_OPC_##M) ", " GAP8_STR(GAP8_XPULP_F3_##M) ", " GAP8_STR( \
      GAP8_XPULP_F7_##M) ", "
/* ".insn i OPC, F3, " (or s, sb) of instruction M. */
#define GAP8_INSN_I(kind, M) \
  ".insn " kind " " GAP8_STR(GAP8_XPULP_OPC_##M) ", " GAP8_STR(GAP8_XPULP_F3_##M) ", "

/* The C function wrappers: xpulp_functions.h, generated from the table, defines one per
 * instruction whose operands are registers only (gap8_<mnemonic>, dots as _) with these. */
#define GAP8_XPULP_RR(name, M)                                                \
  static inline uint32_t name(uint32_t a, uint32_t b) {                       \
    uint32_t r;                                                               \
    __asm__ volatile(GAP8_INSN_R(M) "%0, %1, %2" : "=r"(r) : "r"(a), "r"(b)); \
    return r;                                                                 \
  }
/* The accumulator is rd (read and written): pv.sdot*, p.mac. */
#define GAP8_XPULP_ACC(name, M)                                                 \
  static inline uint32_t name(uint32_t acc, uint32_t a, uint32_t b) {           \
    __asm__ volatile(GAP8_INSN_R(M) "%0, %1, %2" : "+r"(acc) : "r"(a), "r"(b)); \
    return acc;                                                                 \
  }
/* One source, the rs2 field x0: pv.abs, p.abs, p.ext*. */
#define GAP8_XPULP_UNARY(name, M)                                     \
  static inline uint32_t name(uint32_t a) {                           \
    uint32_t r;                                                       \
    __asm__ volatile(GAP8_INSN_R(M) "%0, %1, x0" : "=r"(r) : "r"(a)); \
    return r;                                                         \
  }

#include "xpulp_functions.h"

/* Post-increment loads: returns **p and advances *p by one element (p.lbu / p.lw rd, imm(rs1!)). */
#define GAP8_LOAD_POST(name, type, M)                 \
  static inline uint32_t name(const type** p) {       \
    uint32_t r;                                       \
    __asm__ volatile(GAP8_INSN_I("i", M) "%0, %1, %2" \
                     : "=r"(r), "+r"(*p)              \
                     : "i"(sizeof(type))              \
                     : "memory");                     \
    return r;                                         \
  }

GAP8_LOAD_POST(gap8_p_lbu_post, uint8_t, P_LBU_IRPOST)
GAP8_LOAD_POST(gap8_p_lw_post, uint32_t, P_LW_IRPOST)

/* ---- The rest of PULPv2 (GAP8's cluster ISA as GVSOC runs it), as GAP8_XPULP_* macros ----
 * Each expands to one instruction in its PULPv2 encoding (gvsoc-core isa_pulpv2.py) and yields
 * its result; the semantics are in gap8_model/include/gap8/xpulp.h with their sources.
 * Names follow the mnemonics: GAP8_XPULP_PV_ADD_H = pv.add.h, ..._SC_H = pv.add.sc.h,
 * ..._SCI_H(a, imm) = pv.add.sci.h. Immediates must be integer constant expressions. */

/* rd = op(rs1, rs2): opcode, funct3, funct7. */
#define GAP8_XPULP_R(opc, f3, f7, a, b)                                                          \
  ({                                                                                             \
    uint32_t r_;                                                                                 \
    __asm__ volatile(".insn r " GAP8_STR(opc) ", " GAP8_STR(f3) ", " GAP8_STR(f7) ", %0, %1, %2" \
                     : "=r"(r_)                                                                  \
                     : "r"((uint32_t)(a)), "r"((uint32_t)(b)));                                  \
    r_;                                                                                          \
  })
/* rd = op(rs1), rs2 field x0. */
#define GAP8_XPULP_R1(opc, f3, f7, a)                                                            \
  ({                                                                                             \
    uint32_t r_;                                                                                 \
    __asm__ volatile(".insn r " GAP8_STR(opc) ", " GAP8_STR(f3) ", " GAP8_STR(f7) ", %0, %1, x0" \
                     : "=r"(r_)                                                                  \
                     : "r"((uint32_t)(a)));                                                      \
    r_;                                                                                          \
  })
/* rd = op(rd, rs1, rs2): the instruction reads and writes rd. */
#define GAP8_XPULP_RACC(opc, f3, f7, acc, a, b)                                                  \
  ({                                                                                             \
    uint32_t r_ = (uint32_t)(acc);                                                               \
    __asm__ volatile(".insn r " GAP8_STR(opc) ", " GAP8_STR(f3) ", " GAP8_STR(f7) ", %0, %1, %2" \
                     : "+r"(r_)                                                                  \
                     : "r"((uint32_t)(a)), "r"((uint32_t)(b)));                                  \
    r_;                                                                                          \
  })
/* An I-type view of an encoding whose bits 31..20 are `imm12` (sign-folded for .insn i). */
#define GAP8_XPULP_IMM12(imm12) ((((int)(imm12)) ^ 0x800) - 0x800)
#define GAP8_XPULP_I(opc, f3, imm12, a)                                        \
  ({                                                                           \
    uint32_t r_;                                                               \
    __asm__ volatile(".insn i " GAP8_STR(opc) ", " GAP8_STR(f3) ", %0, %1, %2" \
                     : "=r"(r_)                                                \
                     : "r"((uint32_t)(a)), "i"(GAP8_XPULP_IMM12(imm12)));      \
    r_;                                                                        \
  })
#define GAP8_XPULP_IACC(opc, f3, imm12, acc, a)                                \
  ({                                                                           \
    uint32_t r_ = (uint32_t)(acc);                                             \
    __asm__ volatile(".insn i " GAP8_STR(opc) ", " GAP8_STR(f3) ", %0, %1, %2" \
                     : "+r"(r_)                                                \
                     : "r"((uint32_t)(a)), "i"(GAP8_XPULP_IMM12(imm12)));      \
    r_;                                                                        \
  })
/* Packed SIMD (opcode 0x57): funct6, funct3 0 .h, 1 .b, 4 .sc.h, 5 .sc.b, 6 .sci.h, 7 .sci.b;
 * the 6-bit .sci immediate goes to bit 25 (imm[0]) and bits 24..20 (imm[5:1]). */
#define GAP8_XPULP_SCI12(f6, imm) (((f6) << 6) | (((imm)&1) << 5) | (((imm) >> 1) & 31))
#define GAP8_XPULP_PV(f6, f3, a, b) GAP8_XPULP_R(GAP8_XPULP_OPC_PV_ADD_H, f3, ((f6) << 1), a, b)
#define GAP8_XPULP_PV_ACC(f6, f3, acc, a, b) \
  GAP8_XPULP_RACC(GAP8_XPULP_OPC_PV_ADD_H, f3, ((f6) << 1), acc, a, b)
#define GAP8_XPULP_PV_SCI(f6, f3, a, imm) \
  GAP8_XPULP_I(GAP8_XPULP_OPC_PV_ADD_H, f3, GAP8_XPULP_SCI12(f6, imm), a)
#define GAP8_XPULP_PV_SCI_ACC(f6, f3, acc, a, imm) \
  GAP8_XPULP_IACC(GAP8_XPULP_OPC_PV_ADD_H, f3, GAP8_XPULP_SCI12(f6, imm), acc, a)

/* Instruction M (the suffix of its GAP8_XPULP_*_<M> fields) in each operand shape. */
#define GAP8_XPULP_NAMED_R(M, a, b) \
  GAP8_XPULP_R(GAP8_XPULP_OPC_##M, GAP8_XPULP_F3_##M, GAP8_XPULP_F7_##M, a, b)
#define GAP8_XPULP_NAMED_R1(M, a) \
  GAP8_XPULP_R1(GAP8_XPULP_OPC_##M, GAP8_XPULP_F3_##M, GAP8_XPULP_F7_##M, a)
#define GAP8_XPULP_NAMED_RACC(M, acc, a, b) \
  GAP8_XPULP_RACC(GAP8_XPULP_OPC_##M, GAP8_XPULP_F3_##M, GAP8_XPULP_F7_##M, acc, a, b)
/* .sci: the 6-bit immediate with funct6 = F7 >> 1. */
#define GAP8_XPULP_NAMED_SCI(M, a, imm)               \
  GAP8_XPULP_I(GAP8_XPULP_OPC_##M, GAP8_XPULP_F3_##M, \
               GAP8_XPULP_SCI12(GAP8_XPULP_F7_##M >> 1, imm), a)
#define GAP8_XPULP_NAMED_SCI_ACC(M, acc, a, imm)         \
  GAP8_XPULP_IACC(GAP8_XPULP_OPC_##M, GAP8_XPULP_F3_##M, \
                  GAP8_XPULP_SCI12(GAP8_XPULP_F7_##M >> 1, imm), acc, a)
/* An immediate in funct7's low bits (Is3 of the 16-bit MACs and p.addN) or in the rs2 field. */
#define GAP8_XPULP_NAMED_N(M, is3, a, b) \
  GAP8_XPULP_R(GAP8_XPULP_OPC_##M, GAP8_XPULP_F3_##M, (GAP8_XPULP_F7_##M | ((is3)&31)), a, b)
#define GAP8_XPULP_NAMED_NACC(M, is3, acc, a, b)                                                   \
  GAP8_XPULP_RACC(GAP8_XPULP_OPC_##M, GAP8_XPULP_F3_##M, (GAP8_XPULP_F7_##M | ((is3)&31)), acc, a, \
                  b)
#define GAP8_XPULP_NAMED_I5(M, a, field10) \
  GAP8_XPULP_I(GAP8_XPULP_OPC_##M, GAP8_XPULP_F3_##M, ((GAP8_XPULP_F7_##M << 5) | (field10)), a)
#define GAP8_XPULP_NAMED_I5ACC(M, acc, a, field10)                                               \
  GAP8_XPULP_IACC(GAP8_XPULP_OPC_##M, GAP8_XPULP_F3_##M, ((GAP8_XPULP_F7_##M << 5) | (field10)), \
                  acc, a)

/* pv.<op>{.h,.b,.sc.h,.sc.b}: GAP8_XPULP_PV_<OP>_<FORM>(a, b); .sci: GAP8_XPULP_PV_<OP>_SCI_H
 * / _SCI_B(a, imm). funct6 from GVSOC's table. */
#define GAP8_XPULP_F6_ADD (GAP8_XPULP_F7_PV_ADD_B >> 1)
#define GAP8_XPULP_F6_SUB (GAP8_XPULP_F7_PV_SUB_B >> 1)
#define GAP8_XPULP_F6_AVG (GAP8_XPULP_F7_PV_AVG_B >> 1)
#define GAP8_XPULP_F6_AVGU (GAP8_XPULP_F7_PV_AVGU_B >> 1)
#define GAP8_XPULP_F6_MIN (GAP8_XPULP_F7_PV_MIN_B >> 1)
#define GAP8_XPULP_F6_MINU (GAP8_XPULP_F7_PV_MINU_B >> 1)
#define GAP8_XPULP_F6_MAX (GAP8_XPULP_F7_PV_MAX_B >> 1)
#define GAP8_XPULP_F6_MAXU (GAP8_XPULP_F7_PV_MAXU_B >> 1)
#define GAP8_XPULP_F6_SRL (GAP8_XPULP_F7_PV_SRL_B >> 1)
#define GAP8_XPULP_F6_SRA (GAP8_XPULP_F7_PV_SRA_B >> 1)
#define GAP8_XPULP_F6_SLL (GAP8_XPULP_F7_PV_SLL_B >> 1)
#define GAP8_XPULP_F6_OR (GAP8_XPULP_F7_PV_OR_B >> 1)
#define GAP8_XPULP_F6_XOR (GAP8_XPULP_F7_PV_XOR_B >> 1)
#define GAP8_XPULP_F6_AND (GAP8_XPULP_F7_PV_AND_B >> 1)
#define GAP8_XPULP_F6_DOTUP (GAP8_XPULP_F7_PV_DOTUP_B >> 1)
#define GAP8_XPULP_F6_DOTUSP (GAP8_XPULP_F7_PV_DOTUSP_B >> 1)
#define GAP8_XPULP_F6_DOTSP (GAP8_XPULP_F7_PV_DOTSP_B >> 1)
#define GAP8_XPULP_F6_SDOTUP (GAP8_XPULP_F7_PV_SDOTUP_B >> 1)
#define GAP8_XPULP_F6_SDOTUSP (GAP8_XPULP_F7_PV_SDOTUSP_B >> 1)
#define GAP8_XPULP_F6_SDOTSP (GAP8_XPULP_F7_PV_SDOTSP_B >> 1)
#define GAP8_XPULP_F6_CMPEQ (GAP8_XPULP_F7_PV_CMPEQ_B >> 1)
#define GAP8_XPULP_F6_CMPNE (GAP8_XPULP_F7_PV_CMPNE_B >> 1)
#define GAP8_XPULP_F6_CMPGT (GAP8_XPULP_F7_PV_CMPGT_B >> 1)
#define GAP8_XPULP_F6_CMPGE (GAP8_XPULP_F7_PV_CMPGE_B >> 1)
#define GAP8_XPULP_F6_CMPLT (GAP8_XPULP_F7_PV_CMPLT_B >> 1)
#define GAP8_XPULP_F6_CMPLE (GAP8_XPULP_F7_PV_CMPLE_B >> 1)
#define GAP8_XPULP_F6_CMPGTU (GAP8_XPULP_F7_PV_CMPGTU_B >> 1)
#define GAP8_XPULP_F6_CMPGEU (GAP8_XPULP_F7_PV_CMPGEU_B >> 1)
#define GAP8_XPULP_F6_CMPLTU (GAP8_XPULP_F7_PV_CMPLTU_B >> 1)
#define GAP8_XPULP_F6_CMPLEU (GAP8_XPULP_F7_PV_CMPLEU_B >> 1)
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

#define GAP8_XPULP_PV_ABS_H(a) GAP8_XPULP_NAMED_R1(PV_ABS_H, a)
#define GAP8_XPULP_PV_EXTRACT_H(a, i) GAP8_XPULP_NAMED_SCI(PV_EXTRACT_H, a, i)
#define GAP8_XPULP_PV_EXTRACT_B(a, i) GAP8_XPULP_NAMED_SCI(PV_EXTRACT_B, a, i)
#define GAP8_XPULP_PV_EXTRACTU_H(a, i) GAP8_XPULP_NAMED_SCI(PV_EXTRACTU_H, a, i)
#define GAP8_XPULP_PV_EXTRACTU_B(a, i) GAP8_XPULP_NAMED_SCI(PV_EXTRACTU_B, a, i)
#define GAP8_XPULP_PV_INSERT_H(rd, a, i) GAP8_XPULP_NAMED_SCI_ACC(PV_INSERT_H, rd, a, i)
#define GAP8_XPULP_PV_INSERT_B(rd, a, i) GAP8_XPULP_NAMED_SCI_ACC(PV_INSERT_B, rd, a, i)
#define GAP8_XPULP_PV_SHUFFLE_H(a, sel) GAP8_XPULP_NAMED_R(PV_SHUFFLE_H, a, sel)
#define GAP8_XPULP_PV_SHUFFLE_B(a, sel) GAP8_XPULP_NAMED_R(PV_SHUFFLE_B, a, sel)
#define GAP8_XPULP_PV_SHUFFLE_SCI_H(a, imm) GAP8_XPULP_NAMED_SCI(PV_SHUFFLE_SCI_H, a, imm)
#define GAP8_XPULP_PV_SHUFFLEI0_SCI_B(a, imm) GAP8_XPULP_NAMED_SCI(PV_SHUFFLEI0_SCI_B, a, imm)
#define GAP8_XPULP_PV_SHUFFLEI1_SCI_B(a, imm) GAP8_XPULP_NAMED_SCI(PV_SHUFFLEI1_SCI_B, a, imm)
#define GAP8_XPULP_PV_SHUFFLEI2_SCI_B(a, imm) GAP8_XPULP_NAMED_SCI(PV_SHUFFLEI2_SCI_B, a, imm)
#define GAP8_XPULP_PV_SHUFFLEI3_SCI_B(a, imm) GAP8_XPULP_NAMED_SCI(PV_SHUFFLEI3_SCI_B, a, imm)
#define GAP8_XPULP_PV_SHUFFLE2_H(rd, a, sel) GAP8_XPULP_NAMED_RACC(PV_SHUFFLE2_H, rd, a, sel)
#define GAP8_XPULP_PV_SHUFFLE2_B(rd, a, sel) GAP8_XPULP_NAMED_RACC(PV_SHUFFLE2_B, rd, a, sel)
#define GAP8_XPULP_PV_PACK_H(a, b) GAP8_XPULP_NAMED_R(PV_PACK_H, a, b)
#define GAP8_XPULP_PV_PACKHI_B(rd, a, b) GAP8_XPULP_NAMED_RACC(PV_PACKHI_B, rd, a, b)
#define GAP8_XPULP_PV_PACKLO_B(rd, a, b) GAP8_XPULP_NAMED_RACC(PV_PACKLO_B, rd, a, b)

/* GAP8's own SIMD extensions (gap_sdk GVSOC, ISA subset `gap8`): complex values im:re. */
#define GAP8_XPULP_PV_ADD_H_DIV2(a, b) GAP8_XPULP_NAMED_R(PV_ADD_H_DIV2, a, b)
#define GAP8_XPULP_PV_ADD_H_DIV4(a, b) GAP8_XPULP_NAMED_R(PV_ADD_H_DIV4, a, b)
#define GAP8_XPULP_PV_ADD_B_DIV2(a, b) GAP8_XPULP_NAMED_R(PV_ADD_B_DIV2, a, b)
#define GAP8_XPULP_PV_ADD_B_DIV4(a, b) GAP8_XPULP_NAMED_R(PV_ADD_B_DIV4, a, b)
#define GAP8_XPULP_PV_SUB_H_DIV2(a, b) GAP8_XPULP_NAMED_R(PV_SUB_H_DIV2, a, b)
#define GAP8_XPULP_PV_SUB_H_DIV4(a, b) GAP8_XPULP_NAMED_R(PV_SUB_H_DIV4, a, b)
#define GAP8_XPULP_PV_SUB_B_DIV2(a, b) GAP8_XPULP_NAMED_R(PV_SUB_B_DIV2, a, b)
#define GAP8_XPULP_PV_SUB_B_DIV4(a, b) GAP8_XPULP_NAMED_R(PV_SUB_B_DIV4, a, b)
#define GAP8_XPULP_PV_CPLXMUL_S(a, b) GAP8_XPULP_NAMED_R(PV_CPLXMUL_S, a, b)
#define GAP8_XPULP_PV_CPLXMUL_S_DIV2(a, b) GAP8_XPULP_NAMED_R(PV_CPLXMUL_S_DIV2, a, b)
#define GAP8_XPULP_PV_CPLXMUL_S_DIV4(a, b) GAP8_XPULP_NAMED_R(PV_CPLXMUL_S_DIV4, a, b)
#define GAP8_XPULP_PV_CPLXCONJ_H(a) GAP8_XPULP_NAMED_R1(PV_CPLXCONJ_H, a)
#define GAP8_XPULP_PV_SUBROTMJ_H(a, b) GAP8_XPULP_NAMED_R(PV_SUBROTMJ_H, a, b)
#define GAP8_XPULP_PV_SUBROTMJ_H_DIV2(a, b) GAP8_XPULP_NAMED_R(PV_SUBROTMJ_H_DIV2, a, b)
#define GAP8_XPULP_PV_SUBROTMJ_H_DIV4(a, b) GAP8_XPULP_NAMED_R(PV_SUBROTMJ_H_DIV4, a, b)
#define GAP8_XPULP_PV_PACK_H_H(a, b) GAP8_XPULP_NAMED_R(PV_PACK_H_H, a, b)
#define GAP8_XPULP_PV_PACK_L_H(a, b) GAP8_XPULP_NAMED_R(PV_PACK_L_H, a, b)

/* Scalar ALU. */
#define GAP8_XPULP_P_AVGU(a, b) GAP8_XPULP_NAMED_R(P_AVGU, a, b)
#define GAP8_XPULP_P_SLET(a, b) GAP8_XPULP_NAMED_R(P_SLET, a, b)
#define GAP8_XPULP_P_SLETU(a, b) GAP8_XPULP_NAMED_R(P_SLETU, a, b)
#define GAP8_XPULP_P_ROR(a, b) GAP8_XPULP_NAMED_R(P_ROR, a, b)
#define GAP8_XPULP_P_FF1(a) GAP8_XPULP_NAMED_R1(P_FF1, a)
#define GAP8_XPULP_P_FL1(a) GAP8_XPULP_NAMED_R1(P_FL1, a)
#define GAP8_XPULP_P_CLB(a) GAP8_XPULP_NAMED_R1(P_CLB, a)
#define GAP8_XPULP_P_CNT(a) GAP8_XPULP_NAMED_R1(P_CNT, a)
#define GAP8_XPULP_P_EXTHS(a) GAP8_XPULP_NAMED_R1(P_EXTHS, a)
#define GAP8_XPULP_P_EXTHZ(a) GAP8_XPULP_NAMED_R1(P_EXTHZ, a)
#define GAP8_XPULP_P_EXTBS(a) GAP8_XPULP_NAMED_R1(P_EXTBS, a)
#define GAP8_XPULP_P_EXTBZ(a) GAP8_XPULP_NAMED_R1(P_EXTBZ, a)
/* p.clip / p.clipu rD, rs1, Is2: Is2 in the rs2 field. */
#define GAP8_XPULP_P_CLIP(a, is2) GAP8_XPULP_NAMED_I5(P_CLIP, a, ((is2)&31))
#define GAP8_XPULP_P_CLIPU(a, is2) GAP8_XPULP_NAMED_I5(P_CLIPU, a, ((is2)&31))
#define GAP8_XPULP_P_CLIPR(a, b) GAP8_XPULP_NAMED_R(P_CLIPR, a, b)
#define GAP8_XPULP_P_CLIPUR(a, b) GAP8_XPULP_NAMED_R(P_CLIPUR, a, b)
#define GAP8_XPULP_P_MAC(acc, a, b) GAP8_XPULP_NAMED_RACC(P_MAC, acc, a, b)
#define GAP8_XPULP_P_MSU(acc, a, b) GAP8_XPULP_NAMED_RACC(P_MSU, acc, a, b)
/* Bit fields, immediate forms: Is3 = width - 1 (bits 29..25), Is2 = position (24..20). */
#define GAP8_XPULP_P_EXTRACT(a, is3, is2) \
  GAP8_XPULP_NAMED_I5(P_EXTRACT, a, ((((is3)&31) << 5) | ((is2)&31)))
#define GAP8_XPULP_P_EXTRACTU(a, is3, is2) \
  GAP8_XPULP_NAMED_I5(P_EXTRACTU, a, ((((is3)&31) << 5) | ((is2)&31)))
#define GAP8_XPULP_P_INSERT(rd, a, is3, is2) \
  GAP8_XPULP_NAMED_I5ACC(P_INSERT, rd, a, ((((is3)&31) << 5) | ((is2)&31)))
#define GAP8_XPULP_P_BCLR(a, is3, is2) \
  GAP8_XPULP_NAMED_I5(P_BCLR, a, ((((is3)&31) << 5) | ((is2)&31)))
#define GAP8_XPULP_P_BSET(a, is3, is2) \
  GAP8_XPULP_NAMED_I5(P_BSET, a, ((((is3)&31) << 5) | ((is2)&31)))
/* Register forms: rs2 = (width - 1) << 5 | position. */
#define GAP8_XPULP_P_EXTRACTR(a, f) GAP8_XPULP_NAMED_R(P_EXTRACTR, a, f)
#define GAP8_XPULP_P_EXTRACTUR(a, f) GAP8_XPULP_NAMED_R(P_EXTRACTUR, a, f)
#define GAP8_XPULP_P_INSERTR(rd, a, f) GAP8_XPULP_NAMED_RACC(P_INSERTR, rd, a, f)
#define GAP8_XPULP_P_BCLRR(a, f) GAP8_XPULP_NAMED_R(P_BCLRR, a, f)
#define GAP8_XPULP_P_BSETR(a, f) GAP8_XPULP_NAMED_R(P_BSETR, a, f)

/* 16-bit multiplies and MACs, normalised add/sub (opcode 0x5B): funct7 = variant << 5 | Is3
 * with variant 0 u, 1 hhu, 2 s, 3 hhs (multiplies) or 0 N, 2 uN (add/sub); funct3 0 mul,
 * 4 mul R, 1 mac, 5 mac R, 2 add, 6 add R, 3 sub, 7 sub R. */
#define GAP8_XPULP_MUL16(f3, variant, is3, a, b) \
  GAP8_XPULP_R(GAP8_XPULP_OPC_P_MULUN, f3, (((variant) << 5) | ((is3)&31)), a, b)
#define GAP8_XPULP_MAC16(f3, variant, is3, acc, a, b) \
  GAP8_XPULP_RACC(GAP8_XPULP_OPC_P_MULUN, f3, (((variant) << 5) | ((is3)&31)), acc, a, b)
#define GAP8_XPULP_P_MULS(a, b) GAP8_XPULP_NAMED_N(P_MULSN, 0, a, b)
#define GAP8_XPULP_P_MULHHS(a, b) GAP8_XPULP_NAMED_N(P_MULHHSN, 0, a, b)
#define GAP8_XPULP_P_MULU(a, b) GAP8_XPULP_NAMED_N(P_MULUN, 0, a, b)
#define GAP8_XPULP_P_MULHHU(a, b) GAP8_XPULP_NAMED_N(P_MULHHUN, 0, a, b)
#define GAP8_XPULP_P_MULSN(a, b, n) GAP8_XPULP_NAMED_N(P_MULSN, n, a, b)
#define GAP8_XPULP_P_MULSRN(a, b, n) GAP8_XPULP_NAMED_N(P_MULSRN, n, a, b)
#define GAP8_XPULP_P_MULHHURN(a, b, n) GAP8_XPULP_NAMED_N(P_MULHHURN, n, a, b)
#define GAP8_XPULP_P_MACS(acc, a, b) GAP8_XPULP_NAMED_NACC(P_MACSN, 0, acc, a, b)
#define GAP8_XPULP_P_MACHHU(acc, a, b) GAP8_XPULP_NAMED_NACC(P_MACHHUN, 0, acc, a, b)
#define GAP8_XPULP_P_MACSRN(acc, a, b, n) GAP8_XPULP_NAMED_NACC(P_MACSRN, n, acc, a, b)
#define GAP8_XPULP_P_MACUN(acc, a, b, n) GAP8_XPULP_NAMED_NACC(P_MACUN, n, acc, a, b)
#define GAP8_XPULP_P_ADDN(a, b, n) GAP8_XPULP_NAMED_N(P_ADDN, n, a, b)
#define GAP8_XPULP_P_ADDUN(a, b, n) GAP8_XPULP_NAMED_N(P_ADDUN, n, a, b)
#define GAP8_XPULP_P_ADDRN(a, b, n) GAP8_XPULP_NAMED_N(P_ADDRN, n, a, b)
#define GAP8_XPULP_P_SUBN(a, b, n) GAP8_XPULP_NAMED_N(P_SUBN, n, a, b)
#define GAP8_XPULP_P_SUBURN(a, b, n) GAP8_XPULP_NAMED_N(P_SUBURN, n, a, b)
/* Register forms: rD = (rD +/- rs1 [+ round]) >> rs2[4:0] (variant 1 signed, 3 unsigned). */
#define GAP8_XPULP_P_ADDNR(rd, a, shift) GAP8_XPULP_NAMED_RACC(P_ADDNR, rd, a, shift)
#define GAP8_XPULP_P_SUBURNR(rd, a, shift) GAP8_XPULP_NAMED_RACC(P_SUBURNR, rd, a, shift)

/* Loads and stores of every width (p.lb, p.lbu, p.lh, p.lhu, p.lw = widths 0, 4, 1, 5, 2):
 * rd, imm(rs1!) post-increment; rd, rs2(rs1!) register post-increment; rd, rs2(rs1) register
 * offset (funct7 encodes the width: 0x00 lb, 0x20 lbu, 0x08 lh, 0x28 lhu, 0x10 lw). */
#define GAP8_XPULP_LOAD_POST_IMM(width, p, imm)                                             \
  ({                                                                                        \
    uint32_t r_;                                                                            \
    __asm__ volatile(                                                                       \
        ".insn i " GAP8_STR(GAP8_XPULP_OPC_P_LB_IRPOST) ", " GAP8_STR(width) ", %0, %2(%1)" \
        : "=r"(r_), "+r"(p)                                                                 \
        : "i"(imm)                                                                          \
        : "memory");                                                                        \
    r_;                                                                                     \
  })
#define GAP8_XPULP_LOAD_POST_REG(f7, p, step)                                  \
  ({                                                                           \
    uint32_t r_;                                                               \
    __asm__ volatile(GAP8_INSN_I("r", P_LB_RRPOST) GAP8_STR(f7) ", %0, %1, %2" \
                     : "=r"(r_), "+r"(p)                                       \
                     : "r"(step)                                               \
                     : "memory");                                              \
    r_;                                                                        \
  })
#define GAP8_XPULP_LOAD_REG(f7, p, offset)                                 \
  ({                                                                       \
    uint32_t r_;                                                           \
    __asm__ volatile(GAP8_INSN_I("r", P_LB_RR) GAP8_STR(f7) ", %0, %1, %2" \
                     : "=r"(r_)                                            \
                     : "r"(p), "r"(offset)                                 \
                     : "memory");                                          \
    r_;                                                                    \
  })
/* p.sb/p.sh/p.sw (widths 0, 1, 2): value, imm(rs1!) / rs3(rs1!) / rs3(rs1). */
#define GAP8_XPULP_STORE_POST_IMM(width, value, p, imm)                                   \
  __asm__ volatile(                                                                       \
      ".insn s " GAP8_STR(GAP8_XPULP_OPC_P_SB_IRPOST) ", " GAP8_STR(width) ", %1, %2(%0)" \
      : "+r"(p)                                                                           \
      : "r"(value), "i"(imm)                                                              \
      : "memory")
#define GAP8_XPULP_STORE_POST_REG(width, value, p, step)                                  \
  __asm__ volatile(".insn r " GAP8_STR(GAP8_XPULP_OPC_P_SB_RRPOST) ", " GAP8_STR(         \
                       width) " + " GAP8_STR(GAP8_XPULP_F3_P_SB_RRPOST) ", 0, %2, %0, %1" \
                   : "+r"(p)                                                              \
                   : "r"(value), "r"(step)                                                \
                   : "memory")
#define GAP8_XPULP_STORE_REG(width, value, p, offset)                                 \
  __asm__ volatile(".insn r " GAP8_STR(GAP8_XPULP_OPC_P_SB_RR) ", " GAP8_STR(         \
                       width) " + " GAP8_STR(GAP8_XPULP_F3_P_SB_RR) ", 0, %2, %0, %1" \
                   :                                                                  \
                   : "r"(p), "r"(value), "r"(offset)                                  \
                   : "memory")

/* p.beqimm / p.bneimm are branches: use them in asm blocks, as text; imm5 is the immediate's
 * 5-bit pattern as a literal 0..31 (31 = -1), it sits in the rs2 field. */
#define GAP8_ASM_P_BEQIMM(rs1, imm5, label) \
  GAP8_INSN_I("sb", P_BEQIMM) rs1 ", x" imm5 ", " label "\n\t"
#define GAP8_ASM_P_BNEIMM(rs1, imm5, label) \
  GAP8_INSN_I("sb", P_BNEIMM) rs1 ", x" imm5 ", " label "\n\t"

/* The same instructions as assembler text, for code that must be a single asm block: the body
 * of a hardware loop, where the compiler must not place code of its own. Operands are strings
 * such as "%[acc]" or "a0"; each macro expands to one instruction and a newline. */
#define GAP8_ASM_PV_SUB_B(rd, a, b) GAP8_INSN_R(PV_SUB_B) rd ", " a ", " b "\n\t"
#define GAP8_ASM_PV_MINU_B(rd, a, b) GAP8_INSN_R(PV_MINU_B) rd ", " a ", " b "\n\t"
#define GAP8_ASM_PV_MAXU_B(rd, a, b) GAP8_INSN_R(PV_MAXU_B) rd ", " a ", " b "\n\t"
#define GAP8_ASM_PV_AVGU_B(rd, a, b) GAP8_INSN_R(PV_AVGU_B) rd ", " a ", " b "\n\t"
/* Any packed-SIMD instruction as text: funct6 and funct3 as literals (see GAP8_XPULP_F6_* and
 * GAP8_XPULP_FORM_*), e.g. GAP8_ASM_PV("0x00", "1", "%[r]", "%[a]", "%[b]") = pv.add.b; the
 * .sci form takes the 6-bit immediate as a literal, folded into the I-type immediate by the
 * assembler, e.g. GAP8_ASM_PV_SCI("0x10", "7", "%[r]", "%[a]", "1") = pv.srl.sci.b r, a, 1. */
#define GAP8_ASM_PV(f6, f3, rd, a, b) \
  ".insn r " GAP8_STR(GAP8_XPULP_OPC_PV_ADD_H) ", " f3 ", (" f6 ") << 1, " rd ", " a ", " b "\n\t"
/* (GAS gives | & ^ one precedence, below << and >>: every term is parenthesised.) */
#define GAP8_ASM_PV_SCI(f6, f3, rd, a, imm)                                                 \
  ".insn i " GAP8_STR(GAP8_XPULP_OPC_PV_ADD_H) ", " f3 ", " rd ", " a ", (((((" f6          \
                                               ") << 6) | (((" imm ") & 1) << 5) | (((" imm \
                                               ") >> 1) & 31)) ^ 0x800) - 0x800)\n\t"
/* rd = dot(a, b's low byte in every lane) */
#define GAP8_ASM_PV_DOTUP_SC_B(rd, a, b) GAP8_INSN_R(PV_DOTUP_SC_B) rd ", " a ", " b "\n\t"
/* acc += dot(a, b's low byte in every lane) */
#define GAP8_ASM_PV_SDOTUP_SC_B(acc, a, b) GAP8_INSN_R(PV_SDOTUP_SC_B) acc ", " a ", " b "\n\t"
/* p.lw rd, imm(rs1!): load the word at rs1, then rs1 += imm (imm a literal, e.g. "4"). */
#define GAP8_ASM_P_LW_POST_IMM(rd, imm, rs1) \
  GAP8_INSN_I("i", P_LW_IRPOST) rd ", " imm "(" rs1 ")\n\t"
/* p.lw rd, rs2(rs1!): load the word at rs1, then rs1 += rs2. */
#define GAP8_ASM_P_LW_POST_REG(rd, rs2, rs1) GAP8_INSN_R(P_LW_RRPOST) rd ", " rs1 ", " rs2 "\n\t"
/* p.sw rs2, imm(rs1!): store rs2 at rs1, then rs1 += imm (imm a literal). */
#define GAP8_ASM_P_SW_POST_IMM(rs2, imm, rs1) \
  GAP8_INSN_I("s", P_SW_IRPOST) rs2 ", " imm "(" rs1 ")\n\t"
/* p.lw rd, rs2(rs1): load the word at rs1 + rs2. */
#define GAP8_ASM_P_LW_REG(rd, rs2, rs1) GAP8_INSN_R(P_LW_RR) rd ", " rs1 ", " rs2 "\n\t"

/* Brackets for an asm block with hardware loops. RI5CY wants a loop's first instruction word-
 * aligned and no compressed instruction in its body: BEGIN aligns (with the surrounding code's
 * options, so that the linker keeps the alignment) and turns compressed instructions and linker
 * relaxation off, so that every instruction up to END is 4 bytes and hand-counted offsets hold.
 * Whatever follows BEGIN up to a loop's set-up must then be a whole number of words (it is: every
 * instruction is 4 bytes), and the set-up must sit 4 bytes before the body (lp.setup, lp.setupi)
 * or the body start be given to lp.starti. */
#define GAP8_ASM_HWLOOP_BEGIN ".balign 4\n\t.option push\n\t.option norvc\n\t.option norelax\n\t"
#define GAP8_ASM_HWLOOP_END ".option pop"

/* Hardware loops (loop 0 is the inner one and has priority). The end is the
 * address of the loop's LAST instruction, given as an offset in half-words from the set-up
 * instruction; that last instruction must not be a branch or jump. `loop` is 0 or 1, the other
 * arguments literals, e.g. GAP8_ASM_LP_SETUPI("0", "8", "24").
 * lp.setupi L, count, end: count (12 bits) and end (5 bits) immediate; body starts at pc + 4. */
#define GAP8_ASM_LP_SETUPI(loop, count, end) \
  GAP8_INSN_I("i", LP_SETUPI) "x" loop ", x" end ", " count "\n\t"
/* lp.setup L, rs1, end: count from rs1, end (12 bits) immediate; body starts at pc + 4. */
#define GAP8_ASM_LP_SETUP(loop, count_reg, end) \
  GAP8_INSN_I("i", LP_SETUP) "x" loop ", " count_reg ", " end "\n\t"
/* lp.counti L, count: the count alone (12 bits), for a loop whose start and end are set. */
#define GAP8_ASM_LP_COUNTI(loop, count) GAP8_INSN_I("i", LP_COUNTI) "x" loop ", x0, " count "\n\t"
/* lp.starti L, offset / lp.endi L, offset: start or end address, in half-words from pc. */
#define GAP8_ASM_LP_STARTI(loop, offset) GAP8_INSN_I("i", LP_STARTI) "x" loop ", x0, " offset "\n\t"
#define GAP8_ASM_LP_ENDI(loop, offset) GAP8_INSN_I("i", LP_ENDI) "x" loop ", x0, " offset "\n\t"
/* Assembly-time check of a loop's hand-counted end offset (GAS cannot put a label difference
 * into .insn): label `to` must lie `bytes` after label `from`. GAS can only measure code
 * without branches or jumps between the two labels (their size is decided late). */
#define GAP8_ASM_CHECK_DISTANCE(from, to, bytes) \
  ".if (" to " - " from ") != " bytes            \
  "\n\t"                                         \
  ".error \"hand-counted code distance is wrong (hardware loop end)\"\n\t.endif\n\t"

#endif
