/* The board layer of the mps2-an386 firmware: the link to the host (the UART, or semihosting under
 * QEMU), the counter and the exit. A real board replaces these files (docs/cortex-m4.md, "On a
 * real STM32F4 board"). */
#ifndef PXFLOW_M4_BOARD_H
#define PXFLOW_M4_BOARD_H

#include <stddef.h>
#include <stdint.h>

/* Exit codes of board_exit() besides main's own (QEMU's exit status under semihosting). */
#define BOARD_EXIT_NMI 120
#define BOARD_EXIT_HARD_FAULT 121
#define BOARD_EXIT_MEM_MANAGE 122
#define BOARD_EXIT_BUS_FAULT 123
#define BOARD_EXIT_USAGE_FAULT 124
#define BOARD_EXIT_UNEXPECTED_IRQ 125
#define BOARD_EXIT_NO_LINK 126 /* semihosting link asked for, but QEMU opened no ":tt" */

/* Ends the run through semihosting SYS_EXIT_EXTENDED: QEMU exits with `code` (semihost.c). */
__attribute__((noreturn)) void board_exit(int code);

/* The other semihosting calls (semihost.c): the command line QEMU was given (0, or -1 when it
 * does not fit `size`), SYS_OPEN (a handle, or -1), and SYS_READ / SYS_WRITE, which return the
 * bytes transferred (a read waits for at least one; 0: end of input or an error). */
int board_semihost_cmdline(char *buf, size_t size);
int board_semihost_open(const char *name, uint32_t mode);
size_t board_semihost_read(int handle, uint8_t *buf, size_t n);
size_t board_semihost_write(int handle, const uint8_t *buf, size_t n);

/* The link to the host (link.c), chosen once at start-up: semihosting when QEMU's semihosting
 * command line has the word "link=semihosting", else the UART (initialised here). Reads wait for
 * at least one byte and return how many came (up to `max`), or -1 when the link is closed for
 * good; writes return 0, or -1 when the link is closed. */
typedef enum { BOARD_LINK_UART, BOARD_LINK_SEMIHOSTING } board_link_kind;
board_link_kind board_link_open(void);
const char *board_link_name(void); /* "uart" or "semihosting" */
int board_link_read(uint8_t *buf, size_t max);
int board_link_write(const uint8_t *data, size_t n);

/* UART0 of the board (CMSDK APB UART at 0x40004000, uart_cmsdk.c), 8N1: writes polled, reads
 * from a ring buffer the RX interrupt fills. */
void board_uart_init(void);
void board_uart_write(const uint8_t *data, size_t n);
/* Waits (in WFI) until at least one byte arrived, then returns up to `max` of them. */
size_t board_uart_read(uint8_t *buf, size_t max);

/* SysTick on the processor clock (25 MHz on this board), extended to 64 bits by counting its
 * wraps (systick.c). Under QEMU's -icount shift=N every instruction advances virtual time by
 * 2^N ns, so the count measures instructions, not cycles (docs/cortex-m4.md). */
#define BOARD_SYSTICK_HZ 25000000u
void board_systick_init(void);
uint64_t board_systick_ticks(void);

#endif
