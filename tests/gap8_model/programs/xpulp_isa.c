/* Every PULPv2 instruction the model implements beyond the kernels' subset, emitted with .insn
 * through runtime/xpulp.h, against the results the sources document (the values and their
 * derivations are in tests/gap8_model/test_xpulp_groups.cpp and the riscv-tests vectors).
 * Returns the number of the first failing check; prints "xpulp isa ok" when all pass. */
#include "pmsis.h"
#include "xpulp.h"

static int failures = 0, first_failure = 0, check_no = 0;

static void check(uint32_t got, uint32_t want) {
  ++check_no;
  if (got != want && failures++ == 0) {
    first_failure = check_no;
    printf("check %d: got 0x%x, want 0x%x\n", check_no, got, want);
  }
}

static void simd(void) {
  /* pulp-platform/riscv-tests xpulp-dev pv_avgu test 11: the lane carry is lost */
  check(gap8_pv_avgu_b(0x8F75F8E9u, 0xDD666F70u), 0x366D332Cu);
  check(GAP8_XPULP_PV_OP(AVGU, H, 0xFFFF8000u, 0x00038000u), 0x00010000u);
  check(GAP8_XPULP_PV_OP_SCI(AVGU, SCI_H, 0xED6BE88Au, 11), 0x76BB744Au); /* riscv-tests 8 */
  check(GAP8_XPULP_PV_OP(AVG, H, 0x7FFF0002u, 0x00010002u), 0xC0000002u);
  check(GAP8_XPULP_PV_OP(ADD, SC_H, 0x0001FFFFu, 0xABCD0002u), 0x00030001u);
  check(GAP8_XPULP_PV_OP_SCI(ADD, SCI_B, 0x01020304u, 0x3F), 0x00010203u); /* imm -1 */
  check(GAP8_XPULP_PV_OP(SUB, H, 0x00000001u, 0x00010002u), 0xFFFFFFFFu);
  check(GAP8_XPULP_PV_OP(MIN, B, 0x80017F00u, 0x7F00FF00u), 0x8000FF00u);
  check(GAP8_XPULP_PV_OP(MIN, H, 0x80000001u, 0x7FFF0002u), 0x80000001u);
  check(GAP8_XPULP_PV_OP(MINU, H, 0x80000001u, 0x7FFF0002u), 0x7FFF0001u);
  check(GAP8_XPULP_PV_OP(MAX, B, 0x80017F00u, 0x7F00FF00u), 0x7F017F00u);
  check(GAP8_XPULP_PV_OP(MAXU, SC_H, 0x00018000u, 0x7FFFu), 0x7FFF8000u);
  check(GAP8_XPULP_PV_OP(SRA, H, 0x80000080u, 0x00110004u), 0xC0000008u);
  check(GAP8_XPULP_PV_OP(SRL, H, 0x80000080u, 0x00110004u), 0x40000008u);
  check(GAP8_XPULP_PV_OP(SLL, B, 0x01010181u, 0x00010207u), 0x01020480u);
  check(GAP8_XPULP_PV_OP_SCI(SRA, SCI_B, 0x80402010u, 2), 0xE0100804u);
  check(GAP8_XPULP_PV_OP(OR, SC_B, 0x10203040u, 0x01u), 0x11213141u);
  check(GAP8_XPULP_PV_OP(XOR, H, 0xFFFF0000u, 0x0F0F0F0Fu), 0xF0F00F0Fu);
  check(GAP8_XPULP_PV_OP(AND, SC_H, 0x12345678u, 0xFF00u), 0x12005600u);
  check(GAP8_XPULP_PV_ABS_H(0x8000FFFFu), 0x80000001u);
  check(GAP8_XPULP_PV_EXTRACT_B(0x12F03456u, 2), 0xFFFFFFF0u);
  check(GAP8_XPULP_PV_EXTRACTU_B(0x12F03456u, 2), 0xF0u);
  check(GAP8_XPULP_PV_EXTRACT_H(0x8001F000u, 1), 0xFFFF8001u);
  check(GAP8_XPULP_PV_EXTRACTU_H(0x8001F000u, 1), 0x8001u);
  check(GAP8_XPULP_PV_INSERT_B(0x11223344u, 0xABu, 1), 0x1122AB44u);
  check(GAP8_XPULP_PV_INSERT_H(0x11223344u, 0xABCDu, 1), 0xABCD3344u);
  check(GAP8_XPULP_PV_OP(DOTUP, H, 0xFFFFFFFFu, 0xFFFFFFFFu), 0xFFFC0002u);
  check(GAP8_XPULP_PV_OP(DOTUSP, H, 0x0002FFFFu, 0xFFFF0001u), 0x0000FFFDu);
  check(GAP8_XPULP_PV_OP(DOTSP, B, 0xFF020304u, 0x01FF0102u), (uint32_t)(-1 - 2 + 3 + 8));
  check(GAP8_XPULP_PV_OP(DOTSP, H, 0xFFFF0002u, 0x00030004u), 5u);
  check(GAP8_XPULP_PV_OP_SCI(DOTUP, SCI_B, 0x01020304u, 2), 20u);
  check(GAP8_XPULP_PV_SDOT(SDOTSP, B, 100, 0xFF020304u, 0x01FF0102u), 108u);
  check(GAP8_XPULP_PV_SDOT(SDOTSP, H, 1, 0xFFFF0002u, 0x00030004u), 6u);
  check(GAP8_XPULP_PV_SDOT(SDOTUP, SC_H, 1, 0x00020003u, 0x10005u), 26u);
  check(GAP8_XPULP_PV_SDOT(SDOTUSP, H, 0, 0xFFFF0001u, 0x0001FFFFu), 0x0000FFFEu);
  check(GAP8_XPULP_PV_SDOT_SCI(SDOTSP, SCI_B, 10, 0x01010101u, 0x3E), 2u); /* 10 + 4 x -2 */
  check(GAP8_XPULP_PV_OP(CMPEQ, B, 0x01028004u, 0x01FF8005u), 0xFF00FF00u);
  check(GAP8_XPULP_PV_OP(CMPNE, H, 0x00010002u, 0x00010003u), 0x0000FFFFu);
  check(GAP8_XPULP_PV_OP(CMPGT, B, 0x80017F00u, 0x7F00FF00u), 0x00FFFF00u);
  check(GAP8_XPULP_PV_OP(CMPGTU, B, 0x80017F00u, 0x7F00FF00u), 0xFFFF0000u);
  check(GAP8_XPULP_PV_OP(CMPGE, B, 0x80017F00u, 0x7F00FF00u), 0x00FFFFFFu);
  check(GAP8_XPULP_PV_OP(CMPGEU, B, 0x80017F00u, 0x7F00FF00u), 0xFFFF00FFu);
  check(GAP8_XPULP_PV_OP(CMPLT, B, 0x80017F00u, 0x7F00FF00u), 0xFF000000u);
  check(GAP8_XPULP_PV_OP(CMPLTU, B, 0x80017F00u, 0x7F00FF00u), 0x0000FF00u);
  check(GAP8_XPULP_PV_OP(CMPLE, B, 0x80017F00u, 0x7F00FF00u), 0xFF0000FFu);
  check(GAP8_XPULP_PV_OP(CMPLEU, B, 0x80017F00u, 0x7F00FF00u), 0x0000FFFFu);
  check(GAP8_XPULP_PV_OP_SCI(CMPGTU, SCI_B, 0xFF3F40FFu, 0x3F), 0xFF00FFFFu);
  check(GAP8_XPULP_PV_OP_SCI(CMPLT, SCI_H, 0xFFFE0000u, 0x3F), 0xFFFF0000u);
  check(GAP8_XPULP_PV_SHUFFLE_B(0x44332211u, 0x00010203u), 0x11223344u);
  check(GAP8_XPULP_PV_SHUFFLE_H(0xAAAABBBBu, 0x00000001u), 0xBBBBAAAAu);
  check(GAP8_XPULP_PV_SHUFFLE_SCI_H(0xAAAABBBBu, 1), 0xBBBBAAAAu);
  check(GAP8_XPULP_PV_SHUFFLEI0_SCI_B(0x44332211u, 0x1B), 0x11223344u);
  check(GAP8_XPULP_PV_SHUFFLEI1_SCI_B(0x44332211u, 0x1B), 0x22223344u);
  check(GAP8_XPULP_PV_SHUFFLEI2_SCI_B(0x44332211u, 0x00), 0x33111111u);
  check(GAP8_XPULP_PV_SHUFFLEI3_SCI_B(0x44332211u, 0x3F), 0x44444444u);
  check(GAP8_XPULP_PV_SHUFFLE2_B(0x88776655u, 0x44332211u, 0x04000500u), 0x11552255u);
  check(GAP8_XPULP_PV_SHUFFLE2_H(0x44443333u, 0x22221111u, 0x00030000u), 0x22223333u);
  check(GAP8_XPULP_PV_PACK_H(0x1234ABCDu, 0x5678EF01u), 0xABCDEF01u);
  check(GAP8_XPULP_PV_PACKHI_B(0x11223344u, 0xAAu, 0xBBu), 0xAABB3344u);
  check(GAP8_XPULP_PV_PACKLO_B(0x11223344u, 0xAAu, 0xBBu), 0x1122AABBu);
}

static void gap8_only(void) {
  check(GAP8_XPULP_PV_ADD_H_DIV2(0x7FFF0003u, 0x00010004u), 0xC0000003u);
  check(GAP8_XPULP_PV_ADD_H_DIV4(0x7FFF0003u, 0x00010004u), 0xE0000001u);
  check(GAP8_XPULP_PV_ADD_B_DIV2(0x7F010203u, 0x01010101u), 0xC0010102u);
  check(GAP8_XPULP_PV_SUB_H_DIV2(0x80000000u, 0x00010002u), 0x3FFFFFFFu);
  check(GAP8_XPULP_PV_SUB_B_DIV4(0x00100080u, 0x01010101u), 0xFF03FF1Fu);
  check(GAP8_XPULP_PV_CPLXMUL_S(0x00004000u, 0x40004000u), 0x20002000u);
  check(GAP8_XPULP_PV_CPLXMUL_S(0x80000000u, 0x80000000u), 0x00008000u);
  check(GAP8_XPULP_PV_CPLXMUL_S_DIV2(0x00004000u, 0x40004000u), 0x10001000u);
  check(GAP8_XPULP_PV_CPLXMUL_S_DIV4(0x00004000u, 0x40004000u), 0x08000800u);
  check(GAP8_XPULP_PV_CPLXCONJ_H(0x12345678u), 0xEDCC5678u);
  check(GAP8_XPULP_PV_SUBROTMJ_H(0x00050003u, 0x00020009u), 0x00060003u);
  check(GAP8_XPULP_PV_SUBROTMJ_H_DIV2(0x00050003u, 0x00020009u), 0x00030001u);
  check(GAP8_XPULP_PV_SUBROTMJ_H_DIV4(0x00050003u, 0x00020009u), 0x00010000u);
  check(GAP8_XPULP_PV_PACK_H_H(0x1234ABCDu, 0x5678EF01u), 0x12345678u);
  check(GAP8_XPULP_PV_PACK_L_H(0x1234ABCDu, 0x5678EF01u), 0xABCDEF01u);
}

static void scalar(void) {
  check(GAP8_XPULP_P_AVGU(0xFFFFFFFFu, 3), 1u);
  check(GAP8_XPULP_P_SLET((uint32_t)-1, 0), 1u);
  check(GAP8_XPULP_P_SLETU((uint32_t)-1, 0), 0u);
  check(GAP8_XPULP_P_ROR(0xF83C38CAu, 1), 2082348133u);
  check(GAP8_XPULP_P_ROR(0xF83C38CAu, 32), 0xF83C38CAu);
  check(GAP8_XPULP_P_FF1(0x00010100u), 8u);
  check(GAP8_XPULP_P_FF1(0), 32u);
  check(GAP8_XPULP_P_FL1(0x00010100u), 16u);
  check(GAP8_XPULP_P_FL1(0), 32u);
  check(GAP8_XPULP_P_CLB(1), 30u);
  check(GAP8_XPULP_P_CLB(0xFFFFFFFFu), 31u);
  check(GAP8_XPULP_P_CLB(0), 0u);
  check(GAP8_XPULP_P_CNT(0xF0F00001u), 9u);
  check(GAP8_XPULP_P_EXTHS(0x12348765u), 0xFFFF8765u);
  check(GAP8_XPULP_P_EXTHZ(0x12348765u), 0x8765u);
  check(GAP8_XPULP_P_EXTBS(0x12348765u), 0x65u);
  check(GAP8_XPULP_P_EXTBS(0x12348785u), 0xFFFFFF85u);
  check(GAP8_XPULP_P_EXTBZ(0x12348785u), 0x85u);
  check(GAP8_XPULP_P_CLIP(200, 8), 127u);
  check(GAP8_XPULP_P_CLIP((uint32_t)-200, 8), (uint32_t)-128);
  check(GAP8_XPULP_P_CLIP(5, 0), 0u);
  check(GAP8_XPULP_P_CLIPU(200, 8), 127u);
  check(GAP8_XPULP_P_CLIPU((uint32_t)-5, 8), 0u);
  check(GAP8_XPULP_P_CLIPR((uint32_t)-1000, 100), (uint32_t)-101);
  check(GAP8_XPULP_P_CLIPUR(0xF8F0A0C6u, 0xF0F009C6u), 0u);
  check(GAP8_XPULP_P_MAC(100, 3, 5), 115u);
  check(GAP8_XPULP_P_MSU(100, 3, 5), 85u);
  check(GAP8_XPULP_P_EXTRACT(0xF83C38CAu, 7, 4), 0xFFFFFF8Cu);
  check(GAP8_XPULP_P_EXTRACTU(0xF83C38CAu, 7, 4), 0x8Cu);
  check(GAP8_XPULP_P_INSERT(0x11223344u, 0xABu, 7, 8), 0x1122AB44u);
  check(GAP8_XPULP_P_BCLR(0xFFFFFFFFu, 7, 8), 0xFFFF00FFu);
  check(GAP8_XPULP_P_BSET(0, 3, 30), 0xC0000000u);
  check(GAP8_XPULP_P_EXTRACTR(0xF83C38CAu, (7 << 5) | 4), 0xFFFFFF8Cu);
  check(GAP8_XPULP_P_EXTRACTUR(0xF83C38CAu, (7 << 5) | 4), 0x8Cu);
  check(GAP8_XPULP_P_INSERTR(0x11223344u, 0xABu, (7 << 5) | 8), 0x1122AB44u);
  check(GAP8_XPULP_P_BCLRR(0xFFFFFFFFu, (7 << 5) | 8), 0xFFFF00FFu);
  check(GAP8_XPULP_P_BSETR(0, (7 << 5) | 8), 0x0000FF00u);
  check(GAP8_XPULP_P_MULS(0x7FFF8000u, 0x0001FFFFu), 0x00008000u);
  check(GAP8_XPULP_P_MULU(0x7FFF8000u, 0x0001FFFFu), 0x7FFF8000u);
  check(GAP8_XPULP_P_MULHHS(0x80000000u, 0xFFFF0000u), 0x00008000u);
  check(GAP8_XPULP_P_MULHHU(0x80000000u, 0xFFFF0000u), 0x7FFF8000u);
  check(GAP8_XPULP_P_MULSN(0xFFFFu, 7, 4), 0xFFFFFFFFu);
  check(GAP8_XPULP_P_MULSRN(0xFFFFu, 7, 4), 0u);
  check(GAP8_XPULP_P_MULHHURN(0x00030000u, 0x00010000u, 1), 2u);
  check(GAP8_XPULP_P_MACS(10, 0xFFFFu, 2), 8u);
  check(GAP8_XPULP_P_MACHHU(10, 0xFFFF0000u, 0x00020000u), 10u + 2u * 65535u);
  check(GAP8_XPULP_P_MACSRN(0x7FFFFFFFu, 0, 0, 1), 0xC0000000u); /* 32-bit sum (RTL) */
  check(GAP8_XPULP_P_MACUN(0xFFFFFFF0u, 3, 3, 1), 0x7FFFFFFCu);
  check(GAP8_XPULP_P_ADDN(0xFFFFFFFDu, 0, 1), 0xFFFFFFFEu);
  check(GAP8_XPULP_P_ADDUN(0xFFFFFFFDu, 0, 1), 0x7FFFFFFEu);
  check(GAP8_XPULP_P_ADDRN(6, 0, 2), 2u);
  check(GAP8_XPULP_P_SUBN(0, 3, 1), 0xFFFFFFFEu);
  check(GAP8_XPULP_P_SUBURN(0, 3, 1), 0x7FFFFFFFu);
  check(GAP8_XPULP_P_ADDNR(0xFFFFFFF9u, 3, 1), 0xFFFFFFFEu);
  check(GAP8_XPULP_P_SUBURNR(5, 9, 1), 0x7FFFFFFEu);
}

static uint8_t buffer[16] __attribute__((aligned(4)));

static void memory(void) {
  static const uint8_t init[8] = {0x81, 0x92, 0xA3, 0xB4, 0x05, 0x16, 0x27, 0x38};
  for (int i = 0; i < 8; ++i) buffer[i] = init[i];
  const uint8_t* p = buffer;
  check(GAP8_XPULP_LOAD_POST_IMM(0, p, 1), 0xFFFFFF81u); /* p.lb */
  check(GAP8_XPULP_LOAD_POST_IMM(1, p, 2), 0xFFFFA392u); /* p.lh at buffer + 1: misaligned */
  check(GAP8_XPULP_LOAD_POST_IMM(5, p, 1), 0x05B4u);     /* p.lhu at buffer + 3 */
  check((uint32_t)(p - buffer), 4u);
  const uint32_t two = 2;
  check(GAP8_XPULP_LOAD_POST_REG(0x20, p, two), 0x05u);   /* p.lbu rd, rs2(rs1!) */
  check(GAP8_XPULP_LOAD_POST_REG(0x28, p, two), 0x3827u); /* p.lhu */
  check((uint32_t)(p - buffer), 8u);
  check(GAP8_XPULP_LOAD_REG(0x08, buffer, two), 0xFFFFB4A3u); /* p.lh rd, rs2(rs1) */
  check(GAP8_XPULP_LOAD_REG(0x10, buffer, 4u), 0x38271605u);  /* p.lw */
  check(GAP8_XPULP_LOAD_REG(0x00, buffer, 0u), 0xFFFFFF81u);  /* p.lb */
  uint8_t* q = buffer + 8;
  GAP8_XPULP_STORE_POST_IMM(0, 0xAAu, q, 1);   /* p.sb */
  GAP8_XPULP_STORE_POST_IMM(1, 0xBBCCu, q, 2); /* p.sh at + 9 */
  GAP8_XPULP_STORE_POST_REG(0, 0xDDu, q, two); /* p.sb rs2, rs3(rs1!) at + 11 */
  check((uint32_t)(q - buffer), 13u);
  GAP8_XPULP_STORE_REG(0, 0xEEu, buffer, 13u);   /* p.sb rs2, rs3(rs1) */
  GAP8_XPULP_STORE_REG(1, 0x1122u, buffer, 14u); /* p.sh */
  check(*(const uint32_t*)(buffer + 8), 0xDDBBCCAAu);
  check(*(const uint32_t*)(buffer + 12), 0x1122EE00u | buffer[12]);
  GAP8_XPULP_STORE_REG(2, 0x01020304u, buffer, 12u); /* p.sw */
  check(*(const uint32_t*)(buffer + 12), 0x01020304u);
}

/* The text macros for asm blocks (hardware-loop bodies): SPEC's floor average of two bytes in
 * four instructions, (a & b) + ((a ^ b) >> 1) per lane with pv.srl.sci.b and pv.add.b. */
static void asm_text(void) {
  const uint32_t a = 0x8F75F8E9u, b = 0xDD666F70u;
  uint32_t r, t;
  __asm__ volatile(
      "and %[r], %[a], %[b]\n\t"
      "xor %[t], %[a], %[b]\n\t" GAP8_ASM_PV_SCI("0x10", "7", "%[t]", "%[t]", "1")
          GAP8_ASM_PV("0x00", "1", "%[r]", "%[r]", "%[t]")
      : [r] "=&r"(r), [t] "=&r"(t)
      : [a] "r"(a), [b] "r"(b));
  check(r, 0xB66DB3ACu); /* the 9-bit floor average: what pv.avgu.b does not compute */
  check(GAP8_XPULP_PV_OP_SCI(SRA, SCI_H, 0x80000010u, 0x3F), 0xFFFF0000u); /* 63 & 15 = 15 */
}

static void branches(void) {
  uint32_t taken = 0, x = (uint32_t)-1;
  __asm__ volatile(GAP8_ASM_P_BEQIMM("%[x]", "31", "1f") "li %[t], 5\n\t"
                   "j 2f\n\t"
                   "1: li %[t], 7\n\t"
                   "2:\n\t"
                   : [t] "+r"(taken)
                   : [x] "r"(x));
  check(taken, 7u); /* -1 == imm5 0b11111 */
  __asm__ volatile(GAP8_ASM_P_BNEIMM("%[x]", "31", "1f") "li %[t], 5\n\t"
                   "j 2f\n\t"
                   "1: li %[t], 7\n\t"
                   "2:\n\t"
                   : [t] "+r"(taken)
                   : [x] "r"(x));
  check(taken, 5u);
}

int main(void) {
  simd();
  gap8_only();
  scalar();
  memory();
  asm_text();
  branches();
  if (failures) {
    printf("xpulp isa: %d failures, first at check %d\n", failures, first_failure);
    return first_failure;
  }
  printf("xpulp isa ok: %d checks\n", check_no);
  return 0;
}
