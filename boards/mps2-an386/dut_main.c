/* The Cortex-M4 kernel as a device under test (docs/dut-protocol.md): the dut/ engine with this
 * board's link (link.c: semihosting under hosts/m4qemu, else the UART) and SysTick as the counter,
 * the kernel of kernels/cortex-m4 as the kernel hook. `pxflow check --backends m4-qemu` runs it
 * under qemu-system-arm (hosts/m4qemu). The frame estimate the engine times and sends in RESULT
 * is dut/'s pxdut_estimate_flow, compiled here for the FPU with -ffp-contract=off.
 *
 * The counter: SysTick runs on the 25 MHz processor clock of the board model. Under QEMU's
 * -icount shift=N each instruction advances virtual time by 2^N ns, so one SysTick tick is
 * 40 / 2^N instructions: with N = 3 (M4_ICOUNT_SHIFT, the value hosts/m4qemu passes) exactly 5.
 * The counter hook returns ticks * 5, an instruction count at 125 M per virtual second, and HELLO
 * names the clock "qemu-icount-instructions": it counts instructions, never cycles.
 *
 * M4_DUT_FAULT (0 for the real firmware) builds the fault firmwares of tests/m4qemu: 1 never
 * answers, 2 exits (QEMU ends) in the middle of the first RUN, 3 hangs in the first RUN, 4 sends
 * garbage instead of replies, 5 answers HELLO with protocol version 2, 6 sends RESULTs whose
 * flow_x is one unit in the last place off the estimate the engine computed. */
#include <stdint.h>

#include "board.h"
#include "m4_flow.h"
#include "pxdut.h"

#ifndef M4_ICOUNT_SHIFT
#define M4_ICOUNT_SHIFT 3
#endif
#if M4_ICOUNT_SHIFT != 3
#error "the instruction count is exact only for -icount shift=3 (40 ns per tick / 8 ns)"
#endif
#define M4_INSTRUCTIONS_PER_TICK 5u /* 40 ns per 25 MHz tick / 8 ns per instruction */

#ifndef M4_DUT_FAULT
#define M4_DUT_FAULT 0
#endif
#ifndef M4_DUT_BUILD
#define M4_DUT_BUILD "unknown"
#endif

int pxdut_port_read(uint8_t *buf, int max) {
  return board_link_read(buf, (size_t)max); /* waits for at least one byte; -1: closed */
}

#if M4_DUT_FAULT == 4
/* Garbage: every reply replaced by as many bytes of a fixed pseudo-random sequence, none 0x00,
 * so no frame ever ends (the host must give up by its timeout, not hang). */
int pxdut_port_write(const uint8_t *buf, int len) {
  static uint32_t x = 12345u;
  (void)buf;
  for (int i = 0; i < len; ++i) {
    x ^= x << 13, x ^= x >> 17, x ^= x << 5;
    const uint8_t b = (uint8_t)(x | 1u);
    if (board_link_write(&b, 1) != 0) return -1;
  }
  return 0;
}
#elif M4_DUT_FAULT == 5 || M4_DUT_FAULT == 6
/* A reply changed on its way out and sealed again with a fresh CRC, so that the host sees a
 * well-formed packet that says something wrong: 5, the HELLO reply with protocol
 * version 2; 6, a RESULT that carries an estimate (flags bit 0) with bit 0 of
 * flow_x's IEEE-754 bits flipped: one unit in the last place off what pxdut_estimate_flow
 * computed (docs/dut-protocol.md, section 3: the RESULT body's flags at byte 20, flow_x at 24). */
static void falsify(uint8_t *packet, int32_t n) {
#if M4_DUT_FAULT == 5
  if (n >= 8 && packet[0] == PXDUT_MSG_HELLO_REPLY) packet[2] = 2u, packet[3] = 0u;
#else
  if (n >= 2 + 40 + 4 && packet[0] == PXDUT_MSG_RESULT &&
      (packet[2 + 20] & PXDUT_RESULT_FLAG_ESTIMATE))
    packet[2 + 24] ^= 1u;
#endif
}

int pxdut_port_write(const uint8_t *buf, int len) {
  static uint8_t packet[PXDUT_MAX_PACKET + 8], out[PXDUT_MAX_PACKET + 16];
  int start = 0;
  while (start < len && buf[start] == 0) /* the delimiters before the frame */
    if (board_link_write(&buf[start++], 1) != 0) return -1;
  const int32_t n =
      len - start > 1 ? pxdut_cobs_decode(buf + start, (uint32_t)(len - start - 1), packet) : -1;
  if (n < 6) return board_link_write(buf + start, (size_t)(len - start));
  falsify(packet, n);
  const uint32_t crc = pxdut_crc32(packet, (uint32_t)n - 4u);
  for (int k = 0; k < 4; ++k) packet[n - 4 + k] = (uint8_t)(crc >> (8 * k));
  const uint32_t m = pxdut_cobs_encode(packet, (uint32_t)n, out);
  out[m] = 0u;
  return board_link_write(out, m + 1u);
}
#else
int pxdut_port_write(const uint8_t *buf, int len) { return board_link_write(buf, (size_t)len); }
#endif

uint32_t pxdut_port_cycles(void) {
  return (uint32_t)(board_systick_ticks() * M4_INSTRUCTIONS_PER_TICK); /* mod 2^32 */
}

uint32_t pxdut_port_cycles_hz(void) { return 1000000000u >> M4_ICOUNT_SHIFT; }

void pxdut_port_kernel(const pxdut_params *p, const uint8_t *prev, const uint8_t *next,
                       pxdut_record *out) {
#if M4_DUT_FAULT == 2
  board_exit(3);
#elif M4_DUT_FAULT == 3
  for (;;) __asm__ volatile("" ::: "memory");
#endif
  m4_flow_frame(p, prev, next, out); /* one parameter block and record: the spec core's */
}

/* HELLO's build string: the build id and the link this run uses. */
static const char *build_string(void) {
  static char build[96];
  const char *parts[] = {M4_DUT_BUILD, " link=", board_link_name()};
  size_t n = 0;
  for (size_t k = 0; k < sizeof parts / sizeof parts[0]; ++k)
    for (const char *c = parts[k]; *c && n + 1 < sizeof build; ++c) build[n++] = *c;
  build[n] = 0;
  return build;
}

int main(void) {
  /* SysTick first: besides being the counter, it keeps a timer running, without which QEMU's
   * -icount never wakes a core sleeping in WFI for the UART (docs/cortex-m4.md). */
  board_systick_init();
  board_link_open();
#if M4_DUT_FAULT == 1
  for (;;) __asm__ volatile("wfi");
#endif
  const pxdut_device dev = {"cortex-m4-dsp (mps2-an386)", build_string(),
                            "qemu-icount-instructions"};
  pxdut_serve(&dev);
  return 0; /* the host closed the link */
}
