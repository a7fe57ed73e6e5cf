/* The firmware's byte link to the host, one of two, chosen at start-up (docs/cortex-m4.md,
 * "The link"):
 *
 * - the UART (uart_cmsdk.c), the link a board has and the default: QEMU's CMSDK UART model takes
 *   one byte per main-loop turn, about 20 KB/s;
 * - semihosting (semihost.c), used when QEMU's semihosting command line has the word
 *   "link=semihosting" (hosts/m4qemu passes -semihosting-config ...,arg=link=semihosting with
 *   -serial null): SYS_READ and SYS_WRITE on the ":tt" handles are one read(2) or write(2) of
 *   QEMU's own stdin and stdout per call, whole buffers, megabytes per second.
 *
 * The choice happens once, before the first byte, and never touches the timed part of a run: the
 * kernel and its counter are the same code on either link. A board without a debugger has no
 * semihosting: its firmware is built with BOARD_SEMIHOSTING_LINK 0 and only ever uses its UART. */
#include "board.h"

#ifndef BOARD_SEMIHOSTING_LINK
#define BOARD_SEMIHOSTING_LINK 1
#endif

#define SEMIHOST_MODE_READ 0u  /* "r": ":tt" is QEMU's stdin */
#define SEMIHOST_MODE_WRITE 4u /* "w": ":tt" is QEMU's stdout */

static struct {
  board_link_kind kind;
  int in, out; /* the semihosting handles */
} chosen;

#if BOARD_SEMIHOSTING_LINK
/* Whether the space-separated command line has the word `word`. */
static int has_word(const char *line, const char *word) {
  for (const char *p = line; *p;) {
    while (*p == ' ') ++p;
    const char *w = word;
    while (*w && *p == *w) ++p, ++w;
    if (*w == 0 && (*p == ' ' || *p == 0)) return 1;
    while (*p && *p != ' ') ++p;
  }
  return 0;
}
#endif

board_link_kind board_link_open(void) {
  chosen.kind = BOARD_LINK_UART;
#if BOARD_SEMIHOSTING_LINK
  static char cmdline[256];
  if (board_semihost_cmdline(cmdline, sizeof cmdline) == 0 &&
      has_word(cmdline, "link=semihosting")) {
    chosen.in = board_semihost_open(":tt", SEMIHOST_MODE_READ);
    chosen.out = board_semihost_open(":tt", SEMIHOST_MODE_WRITE);
    if (chosen.in < 0 || chosen.out < 0) board_exit(BOARD_EXIT_NO_LINK);
    chosen.kind = BOARD_LINK_SEMIHOSTING;
    return chosen.kind;
  }
#endif
  board_uart_init();
  return chosen.kind;
}

const char *board_link_name(void) {
  return chosen.kind == BOARD_LINK_UART ? "uart" : "semihosting";
}

int board_link_read(uint8_t *buf, size_t max) {
#if BOARD_SEMIHOSTING_LINK
  if (chosen.kind == BOARD_LINK_SEMIHOSTING) {
    /* Nothing read: QEMU's stdin ended (the host closed the link) or failed. */
    const size_t n = board_semihost_read(chosen.in, buf, max);
    return n > 0 ? (int)n : -1;
  }
#endif
  return (int)board_uart_read(buf, max); /* waits for at least one byte */
}

int board_link_write(const uint8_t *data, size_t n) {
#if BOARD_SEMIHOSTING_LINK
  if (chosen.kind == BOARD_LINK_SEMIHOSTING) {
    while (n > 0) { /* a pipe takes it all at once; a short write is continued */
      const size_t done = board_semihost_write(chosen.out, data, n);
      if (done == 0) return -1; /* QEMU's stdout is closed: the host has gone */
      data += done, n -= done;
    }
    return 0;
  }
#endif
  board_uart_write(data, n);
  return 0;
}
