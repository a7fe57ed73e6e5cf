/* The 4-byte vocabulary of the PX4FLOW firmware (SPEC §7) as the Cortex-M4's own DSP
 * instructions, through the ACLE intrinsics of arm_acle.h (Arm C Language Extensions, section
 * "SIMD32 intrinsics": __usad8, __usada8, __uhadd8; GCC emits exactly one instruction for each).
 * Semantics, from the pseudocode of the ARMv7-M Architecture Reference Manual (ARM DDI 0403E,
 * chapter A7 "Instruction Details", entries UHADD8, USAD8 and USADA8; the same pseudocode is in
 * the A32/T32 ISA manual, ARM DDI 0597):
 *
 *   UHADD8:  sum_i = UInt(Rn<8i+7:8i>) + UInt(Rm<8i+7:8i>)  (a 9-bit value);
 *            Rd<8i+7:8i> = sum_i<8:1>                       (floor((a_i + b_i) / 2) per byte)
 *   USAD8:   Rd = (|a_0 - b_0| + ... + |a_3 - b_3|)<31:0>  (bytes as UInt, 0..1020)
 *   USADA8:  Rd = (UInt(Ra) + |a_0 - b_0| + ... + |a_3 - b_3|)<31:0>  (wraps mod 2^32)
 *
 * UHADD8 is therefore exactly SPEC's avg(a, b) = floor((a + b) / 2) lane by lane: the 9-bit sum
 * keeps the carry that RI5CY's pv.avgu.b drops, it rounds down (not the (a + b + 1) / 2 of
 * x86 pavgb or of URHADD8, which ARMv7-M does not have), it is unsigned (SHADD8 would give
 * (-1 + 1) / 2 = 0 for the bytes 0xFF, 0x01 where UHADD8 gives 0x80), and no carry crosses a
 * lane (each sum_i is its own 9-bit value). tests/m4qemu checks these cases on the emulated core
 * against values worked out from the pseudocode above (m4_selftest_simd.c).
 *
 * Loads: the firmware reads four pixels at any address with *(uint32_t *)&image[off]. ARMv7-M
 * permits an unaligned LDR when CCR.UNALIGN_TRP is 0, its reset value (DDI 0403E, A3.2
 * "Alignment support"; the Cortex-M4 Devices Generic User Guide, ARM DUI 0553A, "Address
 * alignment": LDR, LDRH, STR, STRH may be unaligned, LDM, LDRD, STM, STRD fault).
 * memcpy of 4 bytes is the defined-behaviour spelling of it in C; with -mcpu=cortex-m4 (whose
 * GCC default is -munaligned-access) it compiles to one LDR. */
#ifndef PXFLOW_M4_SIMD_H
#define PXFLOW_M4_SIMD_H

#include <arm_acle.h>
#include <stdint.h>
#include <string.h>

#if !defined(__ARM_FEATURE_SIMD32) || !defined(__ARM_FEATURE_UNALIGNED)
#error "kernels/cortex-m4 needs the DSP extension and unaligned loads (-mcpu=cortex-m4)"
#endif

/* Four consecutive pixels as one word (one LDR; lanes are independent, byte order is moot). */
static inline uint32_t m4_ld4(const uint8_t *p) {
  uint32_t w;
  memcpy(&w, p, 4);
  return w;
}

/* USAD8 */
static inline uint32_t m4_sad4(uint32_t a, uint32_t b) { return __usad8(a, b); }

/* USADA8: acc + USAD8(a, b) */
static inline uint32_t m4_sad4_acc(uint32_t a, uint32_t b, uint32_t acc) {
  return __usada8(a, b, acc);
}

/* UHADD8: floor((a_i + b_i) / 2) per byte */
static inline uint32_t m4_avg4(uint32_t a, uint32_t b) { return __uhadd8(a, b); }

/* The primitives of the shared per-POI kernel (pxflow_spec/poi_kernel.h). */
#define PXFLOW_POI_LD4(p) m4_ld4(p)
#define PXFLOW_POI_SAD4_ACC(acc, a, b) m4_sad4_acc(a, b, acc)
#define PXFLOW_POI_AVG4(a, b) m4_avg4(a, b)

#endif
