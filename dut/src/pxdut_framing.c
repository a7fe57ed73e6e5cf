/* The framing of docs/dut-protocol.md section 1: CRC-32/ISO-HDLC and COBS. */
#include "pxdut.h"

/* Bitwise, reflected polynomial 0xEDB88320, init and final XOR 0xFFFFFFFF: no table, so it costs
 * no RAM or flash to speak of; the frames are short. */
uint32_t pxdut_crc32(const uint8_t *data, uint32_t len) {
  uint32_t crc = 0xFFFFFFFFu;
  for (uint32_t i = 0; i < len; ++i) {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

/* Cheshire and Baker's COBS: each run of up to 254 non-zero bytes is preceded by a code byte, its
 * length + 1; a code below 0xFF stands for the run followed by a zero, the final zero implied. */
uint32_t pxdut_cobs_encode(const uint8_t *in, uint32_t len, uint8_t *out) {
  uint32_t code_at = 0, o = 1;
  uint8_t code = 1;
  for (uint32_t i = 0; i < len; ++i) {
    if (in[i] == 0) {
      out[code_at] = code;
      code_at = o++;
      code = 1;
      continue;
    }
    out[o++] = in[i];
    if (++code == 0xFF) { /* a full group of 254: no zero implied after it */
      out[code_at] = code;
      code = 1;
      if (i + 1 == len) return o; /* the data ends with the group: no empty group after it */
      code_at = o++;
    }
  }
  out[code_at] = code;
  return o;
}

int32_t pxdut_cobs_decode(const uint8_t *in, uint32_t len, uint8_t *out) {
  uint32_t i = 0, o = 0;
  while (i < len) {
    const uint8_t code = in[i++];
    if (code == 0 || i + code - 1u > len) return -1;
    for (uint8_t k = 1; k < code; ++k) out[o++] = in[i++];
    /* A zero follows every group but a 0xFF one, and not after the last group. */
    if (code != 0xFF && i < len) out[o++] = 0;
  }
  return (int32_t)o;
}
