/* The constants of the device-under-test protocol (docs/dut-protocol.md), once: message types,
 * NAK reasons, ERROR codes, flags and sizes. Normative: the device engine (dut/src), the test
 * devices (tests/dut), the boards (boards/) and the host (hosts/dut) all take them from here;
 * the Python device and the page's tables are checked against this file (ctest
 * dut_wire_table). Freestanding C99 and C++: plain unsigned literals, nothing else. */
#ifndef PXDUT_WIRE_H
#define PXDUT_WIRE_H

/* Exchanged in HELLO; host and device must agree exactly (section 2). */
#define PXDUT_PROTOCOL_VERSION 1u

/* Message types (section 3): requests from the host, and the device's replies. A reply to a
 * request that returns data is the request's type with bit 7 set. */
#define PXDUT_MSG_HELLO 0x01u
#define PXDUT_MSG_PARAMS 0x02u
#define PXDUT_MSG_FRAME 0x03u
#define PXDUT_MSG_RUN 0x04u
#define PXDUT_MSG_RECORDS 0x05u
#define PXDUT_MSG_ACK 0x06u
#define PXDUT_MSG_NAK 0x15u
#define PXDUT_MSG_ERROR 0x7Fu
#define PXDUT_MSG_HELLO_REPLY 0x81u
#define PXDUT_MSG_RESULT 0x84u
#define PXDUT_MSG_RECORDS_REPLY 0x85u

/* NAK reasons: why the device discarded a frame (section 1). */
#define PXDUT_NAK_BAD_CRC 1u
#define PXDUT_NAK_BAD_COBS 2u
#define PXDUT_NAK_TOO_LONG 3u
#define PXDUT_NAK_TOO_SHORT 4u

/* ERROR codes (section 3). */
#define PXDUT_ERR_BAD_MESSAGE 1u /* unknown type, wrong body length */
#define PXDUT_ERR_BAD_PARAMS 2u
#define PXDUT_ERR_TOO_LARGE 3u /* for this device's buffers */
#define PXDUT_ERR_NOT_READY 4u /* no PARAMS, or no RUN before RECORDS: a reset loses them */
#define PXDUT_ERR_RANGE 5u
#define PXDUT_ERR_VERSION 6u /* reserved: dut/ answers HELLO with its version, the host decides */
#define PXDUT_ERR_OVERRUN 7u /* RUN: the kernel wrote into the guard records after the run's */

/* Flags: bit 0 of HELLO reply's u16 flags and of RESULT's u32 flags. */
#define PXDUT_HELLO_FLAG_ESTIMATE 1u  /* the device computes the frame estimate (SPEC §5) */
#define PXDUT_RESULT_FLAG_ESTIMATE 1u /* RESULT's estimate is valid */

/* FRAME's u8 image. */
#define PXDUT_IMAGE_PREV 0u
#define PXDUT_IMAGE_NEXT 1u

/* Sizes in bytes. A packet is type, seq, body, CRC-32 (section 1). */
#define PXDUT_PACKET_OVERHEAD 6u    /* type, seq and CRC: a shorter packet is "too short" */
#define PXDUT_MAX_PACKET_MIN 64u    /* HELLO's max_packet is at least this */
#define PXDUT_MAX_PACKET_MAX 65535u /* ... and at most this (u16); the host accepts this much */
#define PXDUT_RECORD_BYTES 32u      /* SPEC §4's record on the wire */
#define PXDUT_HELLO_BODY 2u         /* u16 version */
#define PXDUT_PARAMS_BODY 40u       /* 10 x u32 */
#define PXDUT_FRAME_HEADER 8u       /* u8 image, u8 0, u16 0, u32 offset; then the pixels */
#define PXDUT_RUN_BODY 8u           /* u32 repetitions, u32 warmups */
#define PXDUT_RECORDS_BODY 8u       /* u32 first, u32 count */
#define PXDUT_RESULT_BODY 40u       /* 10 x u32 (section 3) */
/* The HELLO reply's body before its three strings: version, flags, counter_hz, max_packet,
 * reserved, max_pixels, max_pois. */
#define PXDUT_HELLO_REPLY_FIXED 22u
/* The host's FRAME chunks hold at most max_packet - this many pixel bytes. */
#define PXDUT_FRAME_CHUNK_MARGIN 18u
/* A RECORDS reply holds at most (max_packet - this) / PXDUT_RECORD_BYTES records: type, seq,
 * first, count and the CRC. */
#define PXDUT_RECORDS_REPLY_OVERHEAD 14u

#endif
