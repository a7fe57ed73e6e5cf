/* pxdut-faulty: the reference device with one fault (docs/dut-protocol.md section 4), for the
 * fault tests. `pxdut-faulty MODE [N]`; N counts the device's frames sent (replies and NAKs),
 * from 1, or the requests received (flip-request, exit). Every fault but `late`, `slow-alive`
 * and `silent` happens once or from then on, as listed in kModes. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "pxdut.h"
#include "ref_link.h"

typedef enum {
  kNone,
  kDropByte,      /* N: one byte of reply N is lost (its CRC fails) */
  kDropReply,     /* N: reply N is lost entirely (the host times out) */
  kFlipReply,     /* N: one bit of reply N flips */
  kFlipRequest,   /* N: one bit of request N flips (the device NAKs it) */
  kLate,          /* N: every RESULT is sent N ms late */
  kSlowAlive,     /* N: every RESULT is sent N ms late, a keepalive (0x00) every 100 ms till then */
  kGarbage,       /* N: 200 bytes of noise (zeros among them) before reply N */
  kGarbageOnly,   /* noise, never a frame */
  kSilent,        /* reads, never answers */
  kReset,         /* N: state lost (and a boot banner) after reply N */
  kExit,          /* N: exits with status 3 when request N arrives */
  kVersion,       /* HELLO says protocol version 2 */
  kShortResult,   /* RESULT says one record fewer than the grid */
  kExtraRecords,  /* every RECORDS reply carries one record more than asked */
  kShortRecords,  /* every RECORDS reply lacks its last record */
  kWrongField,    /* N: run N's first accepted record has sub[3] off by one */
  kWrongEstimate, /* RESULT's flow_x has its lowest bit flipped */
  kWrongSeq,      /* every RESULT carries its request's seq plus one */
  kOverrun        /* the kernel writes one record past the run's records */
} fault_mode;

static const struct {
  const char *name;
  fault_mode mode;
} kModes[] = {{"none", kNone},
              {"drop-byte", kDropByte},
              {"drop-reply", kDropReply},
              {"flip-reply", kFlipReply},
              {"flip-request", kFlipRequest},
              {"late", kLate},
              {"slow-alive", kSlowAlive},
              {"garbage", kGarbage},
              {"garbage-only", kGarbageOnly},
              {"silent", kSilent},
              {"reset", kReset},
              {"exit", kExit},
              {"version", kVersion},
              {"short-result", kShortResult},
              {"extra-records", kExtraRecords},
              {"short-records", kShortRecords},
              {"wrong-field", kWrongField},
              {"wrong-estimate", kWrongEstimate},
              {"wrong-seq", kWrongSeq},
              {"overrun", kOverrun}};

static fault_mode mode = kNone;
static long arg = 0;
static long sent = 0, received = 0, runs = 0;
static unsigned noise = 12345u;

static unsigned next_noise(void) {
  noise = noise * 1103515245u + 12345u;
  return noise >> 16;
}

static void send_noise(int n) {
  unsigned char buf[256];
  for (int i = 0; i < n; ++i) buf[i] = (unsigned char)(i % 50 == 7 ? 0 : next_noise());
  ref_link_write(buf, n);
}

/* A frame the engine wrote, decoded to patch it: returns the packet length (with CRC) or -1. */
static int open_frame(const uint8_t *frame, int len, uint8_t *packet) {
  return (int)pxdut_cobs_decode(frame, (uint32_t)(len - 1), packet);
}

static int seal_frame(uint8_t *packet, int len, uint8_t *out) {
  const uint32_t crc = pxdut_crc32(packet, (uint32_t)len - 4u);
  for (int i = 0; i < 4; ++i) packet[len - 4 + i] = (uint8_t)(crc >> (8 * i));
  const uint32_t n = pxdut_cobs_encode(packet, (uint32_t)len, out);
  out[n] = 0;
  return (int)n + 1;
}

static uint8_t packet[20000], frame[20200];

int pxdut_port_write(const uint8_t *buf, int len) {
  ++sent;
  int n = open_frame(buf, len, packet);
  const uint8_t type = n >= 6 ? packet[0] : 0;
  switch (mode) {
    case kDropByte:
      if (sent == arg) {
        memcpy(frame, buf, (size_t)len);
        memmove(frame + len / 2, frame + len / 2 + 1, (size_t)(len - len / 2 - 1));
        return ref_link_write(frame, len - 1);
      }
      break;
    case kDropReply:
      if (sent == arg) return 0;
      break;
    case kFlipReply:
      if (sent == arg) {
        memcpy(frame, buf, (size_t)len);
        frame[len / 2] ^= 0x10;
        if (frame[len / 2] == 0) frame[len / 2] = 0x10; /* a bit flip, but never a delimiter */
        return ref_link_write(frame, len);
      }
      break;
    case kLate:
      if (type == PXDUT_MSG_RESULT) usleep((useconds_t)arg * 1000u);
      break;
    case kSlowAlive:
      /* A slow kernel on a device that says it is alive: an empty frame (a lone delimiter after
       * the last frame's) every 100 ms, which restarts the host's wait (docs/dut-protocol.md). */
      if (type == PXDUT_MSG_RESULT)
        for (long waited = 0; waited < arg; waited += 100) {
          static const uint8_t keepalive = 0;
          usleep(100000u);
          ref_link_write(&keepalive, 1);
        }
      break;
    case kGarbage:
      if (sent == arg) send_noise(200);
      break;
    case kReset:
      if (sent == arg + 1) {
        static const uint8_t banner[] = "pxdut-faulty: booting\r\n";
        pxdut_reset();
        ref_link_write(banner, (int)sizeof banner - 1);
        return 0; /* the reply to the request that came in while "rebooting" is lost */
      }
      break;
    case kVersion:
      if (type == PXDUT_MSG_HELLO_REPLY) {
        packet[2] = 2;
        return ref_link_write(frame, seal_frame(packet, n, frame));
      }
      break;
    case kShortResult:
      if (type == PXDUT_MSG_RESULT) {
        packet[2] -= 1;
        return ref_link_write(frame, seal_frame(packet, n, frame));
      }
      break;
    case kWrongSeq:
      if (type == PXDUT_MSG_RESULT) {
        packet[1] = (uint8_t)(packet[1] + 1u);
        return ref_link_write(frame, seal_frame(packet, n, frame));
      }
      break;
    case kWrongEstimate:
      if (type == PXDUT_MSG_RESULT) {
        packet[26] ^= 1; /* flow_x's lowest byte: type, seq, then 24 bytes before it */
        return ref_link_write(frame, seal_frame(packet, n, frame));
      }
      break;
    case kExtraRecords:
      if (type == PXDUT_MSG_RECORDS_REPLY) {
        memmove(packet + n - 4, packet + n - 4 - PXDUT_RECORD_BYTES, PXDUT_RECORD_BYTES);
        /* the last record again */
        return ref_link_write(frame, seal_frame(packet, n + (int)PXDUT_RECORD_BYTES, frame));
      }
      break;
    case kShortRecords:
      if (type == PXDUT_MSG_RECORDS_REPLY) {
        memmove(packet + n - 4 - PXDUT_RECORD_BYTES, packet + n - 4, 4); /* the CRC's room */
        return ref_link_write(frame, seal_frame(packet, n - (int)PXDUT_RECORD_BYTES, frame));
      }
      break;
    default:
      break;
  }
  return ref_link_write(buf, len);
}

int pxdut_port_read(uint8_t *buf, int max) {
  if (mode == kGarbageOnly) {
    const int n = ref_link_read(buf, max);
    if (n > 0) send_noise(64);
    return n < 0 ? n : 0;
  }
  const int n = ref_link_read(buf, max);
  if (mode == kSilent) return n < 0 ? n : 0;
  for (int i = 0; i < n; ++i) {
    if (buf[i] != 0) continue;
    ++received; /* a delimiter: counts empty frames too */
    if (mode == kExit && received == arg) exit(3);
  }
  static int flipped = 0;
  if (mode == kFlipRequest && !flipped && received + 1 >= arg)
    for (int i = n / 2; i < n; ++i)
      if (buf[i] != 0 && (buf[i] ^ 0x04) != 0) {
        buf[i] ^= 0x04; /* once: the device sees a bad CRC and NAKs */
        flipped = 1;
        break;
      }
  return n;
}

uint32_t pxdut_port_cycles(void) { return ref_link_nanoseconds(); }
uint32_t pxdut_port_cycles_hz(void) { return 1000000000u; }

void pxdut_port_kernel(const pxdut_params *p, const uint8_t *prev, const uint8_t *next,
                       pxdut_record *out) {
  pxdut_kernel_portable(p, prev, next, out);
  if (mode == kOverrun) out[pxdut_poi_count(p)] = out[0];
  if (mode != kWrongField || ++runs != arg) return;
  for (uint32_t i = 0; i < pxdut_poi_count(p); ++i)
    if (out[i].status == 2) {
      out[i].sub[3] += 1;
      return;
    }
}

int main(int argc, char **argv) {
  argc = ref_link_open(argc, argv);
  if (argc < 2) {
    fprintf(stderr, "usage: pxdut-faulty MODE [N] [--tcp PORT | --pty]\n");
    return 2;
  }
  size_t m = 0;
  while (m < sizeof kModes / sizeof kModes[0] && strcmp(kModes[m].name, argv[1]) != 0) ++m;
  if (m == sizeof kModes / sizeof kModes[0]) {
    fprintf(stderr, "pxdut-faulty: unknown mode %s\n", argv[1]);
    return 2;
  }
  mode = kModes[m].mode;
  arg = argc > 2 ? atol(argv[2]) : 0;
  static const pxdut_device dev = {"pxdut-faulty", "test", "dut-ref-monotonic-ns"};
  pxdut_serve(&dev);
  return 0;
}
