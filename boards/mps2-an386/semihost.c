/* The semihosting calls the firmware makes (Arm "Semihosting for AArch32 and AArch64", version
 * 2.0; QEMU semihosting/arm-compat-semi.c, do_common_semihosting). On M-profile a call is
 * BKPT 0xAB with the operation in r0 and the address of its parameter block in r1; the result
 * comes back in r0. Needs QEMU's -semihosting-config enable=on; without it (or on a board with no
 * debugger attached) the BKPT is a debug event that stops the core, so a real board's firmware
 * makes none of these calls (docs/cortex-m4.md, "On a real STM32F4 board").
 *
 * - SYS_EXIT_EXTENDED (0x20), block {reason, subcode}: with ADP_Stopped_ApplicationExit
 *   (0x20026) QEMU exits with the subcode as its status.
 * - SYS_GET_CMDLINE (0x15), block {buffer, size}: QEMU copies the command line it was given
 *   (-semihosting-config arg=..., else the -kernel file name) with its terminating 0.
 * - SYS_OPEN (0x01), block {name, mode, strlen(name)}: the name ":tt" is the console; QEMU 7.2
 *   maps it, opened with mode 0 ("r"), to its own host stdin and, with mode 4 ("w"), to its host
 *   stdout (associate_guestfd with STDIN_FILENO / STDOUT_FILENO: a GuestFDHost, not the
 *   -semihosting-config chardev).
 * - SYS_READ (0x06) and SYS_WRITE (0x05), block {handle, buffer, length}: return the number of
 *   bytes NOT transferred (common_semi_rw_cb: length - done). On a GuestFDHost QEMU makes one
 *   read(2) / write(2) of the whole length on the host descriptor (semihosting/syscalls.c
 *   host_read, host_write): a read waits for the first byte and returns all that is there, up to
 *   the length; an end of file or an error transfers nothing. */
#include "board.h"

#define SYS_OPEN 0x01u
#define SYS_WRITE 0x05u
#define SYS_READ 0x06u
#define SYS_GET_CMDLINE 0x15u
#define SYS_EXIT_EXTENDED 0x20u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u

static uint32_t semihost_call(uint32_t op, void *block) {
  register uint32_t r0 __asm__("r0") = op;
  register void *r1 __asm__("r1") = block;
  __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

__attribute__((noreturn)) void board_exit(int code) {
  uint32_t block[2] = {ADP_STOPPED_APPLICATION_EXIT, (uint32_t)code};
  semihost_call(SYS_EXIT_EXTENDED, block);
  for (;;) __asm__ volatile("wfi"); /* not reached under QEMU with semihosting on */
}

int board_semihost_cmdline(char *buf, size_t size) {
  uint32_t block[2] = {(uint32_t)(uintptr_t)buf, (uint32_t)size};
  return semihost_call(SYS_GET_CMDLINE, block) == 0u ? 0 : -1;
}

int board_semihost_open(const char *name, uint32_t mode) {
  uint32_t len = 0;
  while (name[len]) ++len;
  uint32_t block[3] = {(uint32_t)(uintptr_t)name, mode, len};
  return (int)semihost_call(SYS_OPEN, block);
}

size_t board_semihost_read(int handle, uint8_t *buf, size_t n) {
  uint32_t block[3] = {(uint32_t)handle, (uint32_t)(uintptr_t)buf, (uint32_t)n};
  const uint32_t left = semihost_call(SYS_READ, block);
  return left <= n ? n - left : 0u;
}

size_t board_semihost_write(int handle, const uint8_t *buf, size_t n) {
  uint32_t block[3] = {(uint32_t)handle, (uint32_t)(uintptr_t)buf, (uint32_t)n};
  const uint32_t left = semihost_call(SYS_WRITE, block);
  return left <= n ? n - left : 0u;
}
