/* The board layer of the mps2-an386 firmware: the UART, the counter and the exit. A real board
 * replaces these files (docs/cortex-m4.md, "On a real STM32F4 board"). */
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

/* Ends the run through semihosting SYS_EXIT_EXTENDED: QEMU exits with `code` (semihost.c). */
__attribute__((noreturn)) void board_exit(int code);

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
