/* The pxflow device-under-test engine (docs/dut-protocol.md): freestanding C99, static buffers
 * sized at compile time (pxdut_types.h), no malloc, no stdio. A firmware's main() is
 *
 *   static const pxdut_device dev = {"my-board-kernel", "build 2026-12-01", "dut-cycles"};
 *   int main(void) { board_init(); pxdut_serve(&dev); }
 *
 * with the five hooks of pxdut_port.h implemented for the board. */
#ifndef PXDUT_H
#define PXDUT_H

#include <stdint.h>

#include "pxdut_port.h"
#include "pxdut_types.h"
#include "pxdut_wire.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What HELLO says about the device (static strings). HELLO sends at most PXDUT_STRING_MAX bytes of
 * each, the most that lets its reply fit PXDUT_MAX_PACKET: 11 at the smallest packet (64), 75 at
 * the default (256), never above 255 (pxdut_engine.c). */
typedef struct {
  const char *name;  /* implementation name */
  const char *build; /* build id */
  const char *clock; /* what pxdut_port_cycles() counts: "dut-cycles" for a cycle counter */
} pxdut_device;

/* Serves requests until pxdut_port_read() reports the link closed; returns then. */
void pxdut_serve(const pxdut_device *dev);

/* One read from the link and the handling of every frame it completed (for a main loop that
 * does other work). Returns 0, or -1 when the link is closed. */
int pxdut_poll(const pxdut_device *dev);

/* Forgets every state (parameters, frames, last sequence number), as after a reset. */
void pxdut_reset(void);

/* The portable C99 kernel (SWAR, no intrinsics), bit-exact to SPEC §3-§4. */
void pxdut_kernel_portable(const pxdut_params *p, const uint8_t *prev, const uint8_t *next,
                           pxdut_record *out);

/* The POI count of SPEC §2's grid (the spec core's pxflow_poi_count). */
uint32_t pxdut_poi_count(const pxdut_params *p);

/* SPEC §5 without gyro compensation, in float as the firmware (build with -ffp-contract=off): the
 * spec core's pxflow_estimate_flow, compiled once here so that every firmware runs the same
 * code. */
void pxdut_estimate_flow(const pxdut_record *records, uint32_t pois, const pxdut_params *p,
                         pxdut_estimate *out);

/* The framing, for tests and for hosts written in C: CRC-32/ISO-HDLC, COBS. */
uint32_t pxdut_crc32(const uint8_t *data, uint32_t len);
/* Encodes `len` bytes to `out` (room for len + len/254 + 1); returns the encoded length. */
uint32_t pxdut_cobs_encode(const uint8_t *in, uint32_t len, uint8_t *out);
/* Decodes `len` bytes (no 0x00 among them) to `out` (may be `in`); returns the decoded length,
 * or -1 when a code points past the end. */
int32_t pxdut_cobs_decode(const uint8_t *in, uint32_t len, uint8_t *out);

#ifdef __cplusplus
}
#endif

#endif
