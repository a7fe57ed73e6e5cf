/* Start-up for QEMU's mps2-an386: the vector table, the reset handler (FPU on, .data copied,
 * .bss cleared, main called, its value reported by semihosting) and fault handlers that end the
 * run with a distinct exit code instead of hanging. Exception numbers and the system register
 * addresses are the ARMv7-M Architecture Reference Manual's (ARM DDI 0403E): B1.5.2 "Exception
 * number definition", B1.5.3 "The vector table"; CPACR at 0xE000ED88 (B3.2.20, CP10 and CP11 full
 * access enable the FPU). */
#include <stdint.h>

#include "board.h"

extern uint32_t __data_start, __data_end, __data_load, __bss_start__, __bss_end__, __stack_top;
int main(void);

#define CPACR (*(volatile uint32_t *)0xE000ED88u)

void m4_reset_handler(void);
void m4_systick_handler(void);  /* systick.c */
void m4_uart0_rx_handler(void); /* uart_cmsdk.c */

/* A fault is a bug in the firmware: report which one and stop, never spin. */
static void fault(int code) { board_exit(code); }
static void nmi_handler(void) { fault(BOARD_EXIT_NMI); }
static void hard_fault_handler(void) { fault(BOARD_EXIT_HARD_FAULT); }
static void mem_manage_handler(void) { fault(BOARD_EXIT_MEM_MANAGE); }
static void bus_fault_handler(void) { fault(BOARD_EXIT_BUS_FAULT); }
static void usage_fault_handler(void) { fault(BOARD_EXIT_USAGE_FAULT); }
static void unexpected_handler(void) { fault(BOARD_EXIT_UNEXPECTED_IRQ); }

/* Entry 0 is the initial main stack pointer, entry n the handler of exception n (16 system
 * exceptions, then the board's 32 interrupts: only UART0 RX, IRQ 0, is enabled). */
__attribute__((section(".vectors"), used)) static void (*const vector_table[16 + 32])(void) = {
    (void (*)(void))(uintptr_t)&__stack_top,
    m4_reset_handler,
    nmi_handler,
    hard_fault_handler,
    mem_manage_handler,
    bus_fault_handler,
    usage_fault_handler,
    unexpected_handler, /* 7..10 reserved */
    unexpected_handler,
    unexpected_handler,
    unexpected_handler,
    unexpected_handler,  /* 11 SVCall */
    unexpected_handler,  /* 12 DebugMonitor */
    unexpected_handler,  /* 13 reserved */
    unexpected_handler,  /* 14 PendSV */
    m4_systick_handler,  /* 15 SysTick */
    m4_uart0_rx_handler, /* IRQ 0: UART0 RX */
    [17 ... 47] = unexpected_handler,
};

void m4_reset_handler(void) {
  /* The FPU first: the C code below may be compiled to use s-registers. */
  CPACR |= 0xFu << 20;
  __asm__ volatile("dsb\n\tisb" ::: "memory");
  /* FPSCR = 0: round to nearest even, no flush-to-zero, no default NaN (DDI 0403E, A2.5). */
  __asm__ volatile("vmsr fpscr, %0" ::"r"(0u));
  const uint32_t *src = &__data_load;
  for (uint32_t *dst = &__data_start; dst < &__data_end;) *dst++ = *src++;
  for (uint32_t *dst = &__bss_start__; dst < &__bss_end__;) *dst++ = 0;
  board_exit(main());
}
