/* The porting layer of the pxflow device-under-test library: the five functions a porter
 * implements for a board (docs/dut-protocol.md, docs/PORTING.md "Your kernel on your board").
 * Everything else (framing, CRC, resends, the messages) is the engine's (pxdut.h).
 *
 * These names are stable from protocol version 1 on; firmware builds against them. */
#ifndef PXDUT_PORT_H
#define PXDUT_PORT_H

#include <stdint.h>

#include "pxdut_types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Reads up to `max` bytes from the link into `buf`. Returns the number read (may block until at
 * least one byte arrived, or return 0 when none is there yet: pxdut_poll() then returns), or a
 * negative value when the link is closed for good (pxdut_serve() returns). */
int pxdut_port_read(uint8_t *buf, int max);

/* Writes all `len` bytes of `buf` to the link (blocking). Returns 0, or a negative value when the
 * link is closed. */
int pxdut_port_write(const uint8_t *buf, int len);

/* A free-running counter (the CPU cycle counter: DWT->CYCCNT on a Cortex-M, mcycle on RISC-V).
 * Only differences are used, modulo 2^32, so it may wrap; one kernel run must take fewer than
 * 2^32 ticks. */
uint32_t pxdut_port_cycles(void);

/* Ticks per second of pxdut_port_cycles() (the core clock for a cycle counter). */
uint32_t pxdut_port_cycles_hz(void);

/* The kernel under test: writes pxdut_poi_count(p) records in grid order (SPEC §2-§4), every
 * byte defined (fields a status does not define are 0). `prev` and `next` are W*H bytes, rows
 * packed, word aligned. The portable C kernel is one line away:
 *   void pxdut_port_kernel(...) { pxdut_kernel_portable(p, prev, next, out); } */
void pxdut_port_kernel(const pxdut_params *p, const uint8_t *prev, const uint8_t *next,
                       pxdut_record *out);

#ifdef __cplusplus
}
#endif

#endif
