/* UART0 of mps2-an386: an Arm CMSDK APB UART at 0x40004000, its RX interrupt on IRQ 0 and TX on
 * IRQ 1 (QEMU hw/arm/mps2.c: uartbase[0], uartirq[0]). Registers (Cortex-M System Design Kit
 * TRM, ARM DDI 0479C, "APB UART"; QEMU hw/char/cmsdk-apb-uart.c): DATA 0x000, STATE 0x004 (bit 0
 * TX buffer full, bit 1 RX buffer full), CTRL 0x008 (bit 0 TX enable, bit 1 RX enable, bit 3 RX
 * interrupt enable), INTSTATUS 0x00C (write 1 to clear), BAUDDIV 0x010 (at least 16).
 *
 * The UART holds one received byte. The RX interrupt moves each byte into a ring buffer, as a
 * real board must (at 115,200 baud a byte arrives every 87 us, whatever the firmware is doing),
 * and a reader with nothing to read sleeps in WFI until the next byte. Under QEMU this is also
 * the fast path: the emulator hands the UART a byte at a time from its main loop, and an idle
 * core lets that loop run (a core polling STATE got about 13 KB/s here, one sleeping in WFI
 * about 20 KB/s, with a fraction of the host CPU; docs/cortex-m4.md). */
#include "board.h"

#define UART0_BASE 0x40004000u
#define UART_DATA (*(volatile uint32_t *)(UART0_BASE + 0x000u))
#define UART_STATE (*(volatile uint32_t *)(UART0_BASE + 0x004u))
#define UART_CTRL (*(volatile uint32_t *)(UART0_BASE + 0x008u))
#define UART_INTSTATUS (*(volatile uint32_t *)(UART0_BASE + 0x00Cu))
#define UART_BAUDDIV (*(volatile uint32_t *)(UART0_BASE + 0x010u))

#define STATE_TX_FULL (1u << 0)
#define STATE_RX_FULL (1u << 1)
#define CTRL_TX_EN (1u << 0)
#define CTRL_RX_EN (1u << 1)
#define CTRL_RX_INTEN (1u << 3)
#define INT_RX (1u << 1)

/* NVIC interrupt set-enable register 0 (DDI 0403E, B3.4.4 NVIC_ISER0); UART0 RX is IRQ 0. */
#define NVIC_ISER0 (*(volatile uint32_t *)0xE000E100u)
#define UART0_RX_IRQ 0u

#define RING_SIZE 4096u /* a power of two */
static volatile uint8_t ring[RING_SIZE];
static volatile uint32_t ring_head, ring_tail; /* written by the ISR, by the reader */
static volatile uint32_t ring_overflows;

/* Acknowledge first, then empty the UART: a byte that lands after the last STATE read raises
 * INTSTATUS.RX again and the handler runs again. (Acknowledging after the reads would clear the
 * interrupt of a byte that arrived in between: it would sit in the UART with no interrupt, and
 * QEMU, which only delivers a byte when the buffer is empty, would deliver no more.) */
static void drain_rx(void) {
  UART_INTSTATUS = INT_RX;
  while (UART_STATE & STATE_RX_FULL) {
    const uint8_t byte = (uint8_t)UART_DATA;
    if (ring_head - ring_tail < RING_SIZE) {
      ring[ring_head % RING_SIZE] = byte;
      ++ring_head;
    } else {
      ++ring_overflows; /* dropped: the protocol's CRC and resends recover */
    }
  }
}

void m4_uart0_rx_handler(void) { drain_rx(); }

void board_uart_init(void) {
  /* 25 MHz / 217 = 115,200 baud on the real board; QEMU only checks BAUDDIV >= 16. */
  UART_BAUDDIV = 217u;
  UART_CTRL = CTRL_TX_EN | CTRL_RX_EN | CTRL_RX_INTEN;
  NVIC_ISER0 = 1u << UART0_RX_IRQ;
}

void board_uart_write(const uint8_t *data, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    while (UART_STATE & STATE_TX_FULL) {
    }
    UART_DATA = data[i];
  }
}

size_t board_uart_read(uint8_t *buf, size_t max) {
  /* Interrupts masked while the ring is checked, so that a byte arriving between the check and
   * the WFI still wakes it (WFI wakes on a pending interrupt even when PRIMASK masks it,
   * DDI 0403E B1.5.19). */
  __asm__ volatile("cpsid i" ::: "memory");
  while (ring_head == ring_tail) {
    drain_rx(); /* a byte the interrupt missed is read here all the same */
    if (ring_head != ring_tail) break;
    __asm__ volatile("wfi\n\tcpsie i\n\tcpsid i" ::: "memory");
  }
  size_t n = 0;
  while (n < max && ring_tail != ring_head) {
    buf[n++] = ring[ring_tail % RING_SIZE];
    ++ring_tail;
  }
  __asm__ volatile("cpsie i" ::: "memory");
  return n;
}
