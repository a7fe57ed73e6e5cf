/* The protocol engine of docs/dut-protocol.md on the device: collects bytes up to each 0x00,
 * checks the frame (COBS, length, CRC), answers duplicates from the stored reply and executes
 * new requests. Every buffer is static and sized by pxdut_types.h; nothing is allocated. */
#include "pxdut.h"

#if PXDUT_MAX_PACKET < PXDUT_MAX_PACKET_MIN || PXDUT_MAX_PACKET > PXDUT_MAX_PACKET_MAX
#error "PXDUT_MAX_PACKET must be 64 .. 65535 (docs/dut-protocol.md section 1)"
#endif

#ifndef PXDUT_COMPUTE_ESTIMATE
#define PXDUT_COMPUTE_ESTIMATE 1 /* the device runs SPEC §5 itself and RESULT carries it */
#endif

#if PXDUT_PARAMS_BODY != 4u * PXFLOW_PARAM_FIELDS || PXDUT_RECORD_BYTES != PXFLOW_RECORD_BYTES
#error "the wire's PARAMS body and record are the spec core's parameter block and record"
#endif

/* Guard records after the run's records: filled with a sentinel before RUN calls the kernel and
 * checked after, so a kernel that writes past its output answers ERROR 7 instead of passing. */
#define PXDUT_GUARD_RECORDS 2u
#define PXDUT_GUARD_BYTE 0xA5u

#define PXDUT_ENCODED_MAX (PXDUT_MAX_PACKET + PXDUT_MAX_PACKET / 254u + 2u)

/* Every reply fits one packet of PXDUT_MAX_PACKET bytes (type, seq, body, CRC), whatever the
 * device's strings: HELLO's three strings and ERROR's text are cut to PXDUT_STRING_MAX bytes, the
 * most that lets HELLO's reply (2 + 22 + 3 x (1 + n) + 4 bytes) fit, and never above 255 (a
 * string's length is a u8): 11 bytes at the smallest packet (64), 75 at the default (256). */
#define PXDUT_STRING_FIT \
  ((PXDUT_MAX_PACKET - PXDUT_PACKET_OVERHEAD - PXDUT_HELLO_REPLY_FIXED) / 3u - 1u)
#define PXDUT_STRING_MAX (PXDUT_STRING_FIT < 255u ? PXDUT_STRING_FIT : 255u)
#define PXDUT_HELLO_REPLY_MAX \
  (PXDUT_PACKET_OVERHEAD + PXDUT_HELLO_REPLY_FIXED + 3u * (1u + PXDUT_STRING_MAX))
#define PXDUT_ERROR_REPLY_MAX (PXDUT_PACKET_OVERHEAD + 2u + 1u + PXDUT_STRING_MAX)
#define PXDUT_RESULT_REPLY (PXDUT_PACKET_OVERHEAD + PXDUT_RESULT_BODY)
#define PXDUT_RECORDS_REPLY_MIN (PXDUT_RECORDS_REPLY_OVERHEAD + PXDUT_RECORD_BYTES)
#if PXDUT_HELLO_REPLY_MAX > PXDUT_MAX_PACKET || PXDUT_ERROR_REPLY_MAX > PXDUT_MAX_PACKET || \
    PXDUT_RESULT_REPLY > PXDUT_MAX_PACKET || PXDUT_RECORDS_REPLY_MIN > PXDUT_MAX_PACKET
#error "a reply of the engine does not fit PXDUT_MAX_PACKET bytes"
#endif

static struct {
  uint8_t rx[PXDUT_ENCODED_MAX]; /* the frame being received, decoded in place */
  uint32_t rx_len;
  int rx_overflow;
  uint8_t packet[PXDUT_MAX_PACKET];  /* the reply being built */
  uint8_t tx[PXDUT_ENCODED_MAX + 1]; /* the last reply, encoded: resent for a duplicate */
  uint32_t tx_len;
  int have_last;
  uint8_t last_seq;
  uint32_t last_crc;
  pxdut_params params;
  int params_ok, run_ok;
  uint32_t pois;
  uint32_t frames[2][(PXDUT_MAX_PIXELS + 3u) / 4u];           /* prev, next: words, so aligned */
  pxdut_record records[PXDUT_MAX_POIS + PXDUT_GUARD_RECORDS]; /* the run's, then its guard */
} g;

static uint32_t get_u16(const uint8_t *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8; }
static uint32_t get_u32(const uint8_t *p) { return get_u16(p) | get_u16(p + 2) << 16; }
static uint8_t *put_u16(uint8_t *p, uint32_t v) {
  p[0] = (uint8_t)v;
  p[1] = (uint8_t)(v >> 8);
  return p + 2;
}
static uint8_t *put_u32(uint8_t *p, uint32_t v) { return put_u16(put_u16(p, v), v >> 16); }
static uint8_t *put_string(uint8_t *p, const char *s) {
  uint32_t n = 0;
  while (s && s[n] && n < PXDUT_STRING_MAX) ++n;
  *p++ = (uint8_t)n;
  for (uint32_t i = 0; i < n; ++i) *p++ = (uint8_t)s[i];
  return p;
}

/* Encodes packet[0 .. body_end) plus its CRC into `out` with the delimiter; returns the length. */
static uint32_t seal(uint8_t *end, uint8_t *out) {
  const uint32_t len = (uint32_t)(end - g.packet);
  put_u32(end, pxdut_crc32(g.packet, len));
  const uint32_t n = pxdut_cobs_encode(g.packet, len + 4u, out);
  out[n] = 0;
  return n + 1u;
}

/* Sends the reply built in packet[] up to `end` and keeps it for a duplicate request. */
static void reply(uint8_t *end) {
  g.tx_len = seal(end, g.tx);
  pxdut_port_write(g.tx, (int)g.tx_len);
}

static uint8_t *begin(uint8_t type, uint8_t seq) {
  g.packet[0] = type;
  g.packet[1] = seq;
  return g.packet + 2;
}

static void error_reply(uint8_t seq, uint32_t code, const char *text) {
  reply(put_string(put_u16(begin(PXDUT_MSG_ERROR, seq), code), text));
}

static void nak(uint8_t reason) {
  uint8_t out[16];
  uint8_t *p = begin(PXDUT_MSG_NAK, 0);
  *p++ = reason;
  /* The NAK is built in packet[] but not kept: the stored reply stays in tx[]. */
  pxdut_port_write(out, (int)seal(p, out));
}

static void on_hello(const pxdut_device *dev, uint8_t seq, const uint8_t *body, uint32_t n) {
  if (n != PXDUT_HELLO_BODY) {
    error_reply(seq, PXDUT_ERR_BAD_MESSAGE, "HELLO body is u16 version");
    return;
  }
  uint8_t *p = begin(PXDUT_MSG_HELLO_REPLY, seq);
  p = put_u16(p, PXDUT_PROTOCOL_VERSION);
  p = put_u16(p, PXDUT_COMPUTE_ESTIMATE ? PXDUT_HELLO_FLAG_ESTIMATE : 0u);
  p = put_u32(p, pxdut_port_cycles_hz());
  p = put_u16(p, PXDUT_MAX_PACKET);
  p = put_u16(p, 0);
  p = put_u32(p, PXDUT_MAX_PIXELS);
  p = put_u32(p, PXDUT_MAX_POIS);
  p = put_string(p, dev->name);
  p = put_string(p, dev->build);
  p = put_string(p, dev->clock);
  (void)body; /* a host of another version still gets our version and decides */
  reply(p);
}

static void on_params(uint8_t seq, const uint8_t *body, uint32_t n) {
  g.params_ok = g.run_ok = 0;
  if (n != PXDUT_PARAMS_BODY) {
    error_reply(seq, PXDUT_ERR_BAD_MESSAGE, "PARAMS body is 10 x u32");
    return;
  }
  pxdut_params q;
  uint32_t *fields[PXFLOW_PARAM_FIELDS] = {&q.width,         &q.height,      &q.search_radius,
                                           &q.tile,          &q.blocks,      &q.feature_threshold,
                                           &q.sad_threshold, &q.hist_filter, &q.min_count,
                                           &q.gyro_comp};
  for (uint32_t i = 0; i < PXFLOW_PARAM_FIELDS; ++i) *fields[i] = get_u32(body + 4 * i);
  if (q.gyro_comp != 0u) {
    error_reply(seq, PXDUT_ERR_BAD_PARAMS, "gyro compensation is not supported");
    return;
  }
  /* SPEC §1's limits, the spec core's (the host's validate() checks the same ones). */
  const pxflow_params_problem problem = pxflow_check_params(&q);
  if (problem != PXFLOW_PARAMS_OK) {
    error_reply(seq, PXDUT_ERR_BAD_PARAMS, pxflow_params_problem_text(problem));
    return;
  }
  const uint32_t pois = pxdut_poi_count(&q);
  if (q.width * q.height > PXDUT_MAX_PIXELS) {
    error_reply(seq, PXDUT_ERR_TOO_LARGE, "frame larger than PXDUT_MAX_PIXELS");
    return;
  }
  if (pois > PXDUT_MAX_POIS) {
    error_reply(seq, PXDUT_ERR_TOO_LARGE, "grid larger than PXDUT_MAX_POIS");
    return;
  }
  g.params = q;
  g.pois = pois;
  g.params_ok = 1;
  reply(begin(PXDUT_MSG_ACK, seq));
}

static void on_frame(uint8_t seq, const uint8_t *body, uint32_t n) {
  if (n <= PXDUT_FRAME_HEADER || body[0] > PXDUT_IMAGE_NEXT) {
    error_reply(seq, PXDUT_ERR_BAD_MESSAGE, "FRAME body is image, 0, 0, offset, bytes");
    return;
  }
  if (!g.params_ok) {
    error_reply(seq, PXDUT_ERR_NOT_READY, "no PARAMS since the device started");
    return;
  }
  const uint32_t offset = get_u32(body + 4), len = n - PXDUT_FRAME_HEADER;
  if (offset > g.params.width * g.params.height ||
      len > g.params.width * g.params.height - offset) {
    error_reply(seq, PXDUT_ERR_RANGE, "FRAME bytes outside W*H");
    return;
  }
  uint8_t *dst = (uint8_t *)g.frames[body[0]] + offset;
  for (uint32_t i = 0; i < len; ++i) dst[i] = body[PXDUT_FRAME_HEADER + i];
  g.run_ok = 0;
  reply(begin(PXDUT_MSG_ACK, seq));
}

static void on_run(uint8_t seq, const uint8_t *body, uint32_t n) {
  if (n != PXDUT_RUN_BODY) {
    error_reply(seq, PXDUT_ERR_BAD_MESSAGE, "RUN body is u32 repetitions, u32 warmups");
    return;
  }
  if (!g.params_ok) {
    error_reply(seq, PXDUT_ERR_NOT_READY, "no PARAMS since the device started");
    return;
  }
  const uint32_t reps = get_u32(body), warmups = get_u32(body + 4);
  if (reps < 1u) {
    error_reply(seq, PXDUT_ERR_BAD_MESSAGE, "RUN needs at least 1 repetition");
    return;
  }
  const uint8_t *prev = (const uint8_t *)g.frames[0], *next = (const uint8_t *)g.frames[1];
  g.run_ok = 0;
  uint8_t *guard = (uint8_t *)&g.records[g.pois];
  const uint32_t guard_bytes = PXDUT_GUARD_RECORDS * (uint32_t)sizeof(pxdut_record);
  for (uint32_t i = 0; i < guard_bytes; ++i) guard[i] = PXDUT_GUARD_BYTE;
  pxdut_estimate est = {0.0f, 0.0f, 0, 0};
  for (uint32_t i = 0; i < warmups; ++i) pxdut_port_kernel(&g.params, prev, next, g.records);
  uint32_t lo = 0, hi = 0, fastest = 0xFFFFFFFFu;
  for (uint32_t i = 0; i < reps; ++i) {
    const uint32_t t0 = pxdut_port_cycles();
    pxdut_port_kernel(&g.params, prev, next, g.records);
    if (PXDUT_COMPUTE_ESTIMATE) pxdut_estimate_flow(g.records, g.pois, &g.params, &est);
    const uint32_t ticks = pxdut_port_cycles() - t0; /* mod 2^32 */
    if (ticks < fastest) fastest = ticks;
    const uint32_t sum = lo + ticks;
    hi += sum < lo ? 1u : 0u; /* the 64-bit total without 64-bit arithmetic */
    lo = sum;
  }
  for (uint32_t i = 0; i < guard_bytes; ++i)
    if (guard[i] != PXDUT_GUARD_BYTE) {
      error_reply(seq, PXDUT_ERR_OVERRUN, "the kernel wrote past the run's records");
      return;
    }
  g.run_ok = 1;
  uint8_t *p = begin(PXDUT_MSG_RESULT, seq);
  p = put_u32(p, g.pois);
  p = put_u32(p, reps);
  p = put_u32(put_u32(p, lo), hi);
  p = put_u32(p, fastest);
  p = put_u32(p, PXDUT_COMPUTE_ESTIMATE ? PXDUT_RESULT_FLAG_ESTIMATE : 0u);
  union {
    float f;
    uint32_t u;
  } bits;
  bits.f = est.flow_x;
  p = put_u32(p, bits.u);
  bits.f = est.flow_y;
  p = put_u32(p, bits.u);
  p = put_u32(p, (uint32_t)est.quality);
  p = put_u32(p, (uint32_t)est.meancount);
  reply(p);
}

static uint8_t *put_record(uint8_t *p, const pxdut_record *r) {
  pxflow_record_to_bytes(r, p);
  return p + PXFLOW_RECORD_BYTES;
}

#define PXDUT_RECORDS_PER_REPLY \
  ((PXDUT_MAX_PACKET - PXDUT_RECORDS_REPLY_OVERHEAD) / PXDUT_RECORD_BYTES)

static void on_records(uint8_t seq, const uint8_t *body, uint32_t n) {
  if (n != PXDUT_RECORDS_BODY) {
    error_reply(seq, PXDUT_ERR_BAD_MESSAGE, "RECORDS body is u32 first, u32 count");
    return;
  }
  if (!g.run_ok) {
    error_reply(seq, PXDUT_ERR_NOT_READY, "no RUN since the last PARAMS or FRAME");
    return;
  }
  const uint32_t first = get_u32(body), count = get_u32(body + 4);
  if (count < 1u || count > PXDUT_RECORDS_PER_REPLY || first > g.pois || count > g.pois - first) {
    error_reply(seq, PXDUT_ERR_RANGE, "RECORDS range outside the run's records or reply size");
    return;
  }
  uint8_t *p = put_u32(put_u32(begin(PXDUT_MSG_RECORDS_REPLY, seq), first), count);
  for (uint32_t i = 0; i < count; ++i) p = put_record(p, &g.records[first + i]);
  reply(p);
}

/* One complete frame in rx[0 .. rx_len). */
static void on_frame_received(const pxdut_device *dev) {
  if (g.rx_overflow) {
    nak(PXDUT_NAK_TOO_LONG);
    return;
  }
  if (g.rx_len == 0u) return; /* an empty frame: a sender's resynchronisation */
  const int32_t n = pxdut_cobs_decode(g.rx, g.rx_len, g.rx);
  if (n < 0) {
    nak(PXDUT_NAK_BAD_COBS);
    return;
  }
  if (n < (int32_t)PXDUT_PACKET_OVERHEAD) {
    nak(PXDUT_NAK_TOO_SHORT);
    return;
  }
  const uint32_t len = (uint32_t)n - 4u, crc = get_u32(g.rx + len);
  if (pxdut_crc32(g.rx, len) != crc) {
    nak(PXDUT_NAK_BAD_CRC);
    return;
  }
  const uint8_t type = g.rx[0], seq = g.rx[1];
  const uint8_t *body = g.rx + 2;
  const uint32_t body_len = len - 2u;
  if (type != PXDUT_MSG_HELLO && g.have_last && seq == g.last_seq && crc == g.last_crc) {
    pxdut_port_write(g.tx, (int)g.tx_len); /* its reply was lost: the same reply again */
    return;
  }
  g.have_last = 1;
  g.last_seq = seq;
  g.last_crc = crc;
  switch (type) {
    case PXDUT_MSG_HELLO: {
      on_hello(dev, seq, body, body_len);
      return;
    }
    case PXDUT_MSG_PARAMS: {
      on_params(seq, body, body_len);
      return;
    }
    case PXDUT_MSG_FRAME: {
      on_frame(seq, body, body_len);
      return;
    }
    case PXDUT_MSG_RUN: {
      on_run(seq, body, body_len);
      return;
    }
    case PXDUT_MSG_RECORDS: {
      on_records(seq, body, body_len);
      return;
    }
    default: {
      error_reply(seq, PXDUT_ERR_BAD_MESSAGE, "unknown message type");
      return;
    }
  }
}

static void on_byte(const pxdut_device *dev, uint8_t byte) {
  if (byte == 0) {
    on_frame_received(dev);
    g.rx_len = 0;
    g.rx_overflow = 0;
    return;
  }
  if (g.rx_len < sizeof g.rx)
    g.rx[g.rx_len++] = byte;
  else
    g.rx_overflow = 1;
}

int pxdut_poll(const pxdut_device *dev) {
  uint8_t chunk[64];
  const int n = pxdut_port_read(chunk, (int)sizeof chunk);
  if (n < 0) return -1;
  for (int i = 0; i < n; ++i) on_byte(dev, chunk[i]);
  return 0;
}

void pxdut_serve(const pxdut_device *dev) {
  while (pxdut_poll(dev) == 0) {
  }
}

void pxdut_reset(void) {
  g.rx_len = 0;
  g.rx_overflow = 0;
  g.have_last = 0;
  g.params_ok = 0;
  g.run_ok = 0;
  g.tx_len = 0;
}
