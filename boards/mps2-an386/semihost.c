/* The one semihosting call the firmware needs: SYS_EXIT_EXTENDED (operation 0x20), whose
 * parameter block is {reason, subcode}; with the reason ADP_Stopped_ApplicationExit (0x20026)
 * QEMU exits with the subcode as its status (Arm "Semihosting for AArch32 and AArch64", version
 * 2.0, SYS_EXIT_EXTENDED; QEMU semihosting/arm-compat-semi.c). On M-profile the call is
 * BKPT 0xAB with the operation in r0 and the block's address in r1. Needs QEMU's
 * -semihosting-config enable=on; without it the BKPT is a debug event that stops the core. */
#include "board.h"

__attribute__((noreturn)) void board_exit(int code) {
  const uint32_t block[2] = {0x20026u, (uint32_t)code};
  register uint32_t r0 __asm__("r0") = 0x20u;
  register const uint32_t *r1 __asm__("r1") = block;
  __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
  for (;;) __asm__ volatile("wfi"); /* not reached under QEMU with semihosting on */
}
