#!/usr/bin/env python3
"""A device under test in Python and numpy: the worked example for prototyping a port before
writing C. It speaks docs/dut-protocol.md version 1 on stdin/stdout and implements SPEC.md
sections 2-5 with whole-array numpy operations (not the firmware's shape). Checked by
    pxflow check --dut "py=exec:python3 tests/dut/pxdut_numpy.py" --require py
Its own code throughout: COBS and the frame handling are written from the protocol page, and the
CRC is zlib's crc32 (CRC-32/ISO-HDLC, the protocol's CRC), a second implementation beside dut/'s.
"""
import os
import struct
import sys
import time
import zlib

try:
    import numpy as np
    from numpy.lib.stride_tricks import sliding_window_view
except ImportError:  # one line for pxflow to show beside its "device went away"
    sys.exit(f"pxdut_numpy.py: {sys.executable} has no numpy: install python3-numpy (Debian) "
             "or give a python3 that has it (e.g. exec:/usr/bin/python3)")

# The protocol's numbers, named as dut/include/pxdut_wire.h names them without its PXDUT_ (the
# ctest dut_wire_table checks every one against the header, and that no code is written bare).
PROTOCOL_VERSION = 1
MSG_HELLO = 0x01
MSG_PARAMS = 0x02
MSG_FRAME = 0x03
MSG_RUN = 0x04
MSG_RECORDS = 0x05
MSG_ACK = 0x06
MSG_NAK = 0x15
MSG_ERROR = 0x7F
MSG_HELLO_REPLY = 0x81
MSG_RESULT = 0x84
MSG_RECORDS_REPLY = 0x85
NAK_BAD_CRC, NAK_BAD_COBS, NAK_TOO_LONG, NAK_TOO_SHORT = 1, 2, 3, 4
ERR_BAD_MESSAGE, ERR_BAD_PARAMS, ERR_TOO_LARGE, ERR_NOT_READY, ERR_RANGE = 1, 2, 3, 4, 5
HELLO_FLAG_ESTIMATE = RESULT_FLAG_ESTIMATE = 1
PACKET_OVERHEAD = 6
RECORD_BYTES = 32
PARAMS_BODY = 40
FRAME_HEADER = RUN_BODY = RECORDS_BODY = 8
RECORDS_REPLY_OVERHEAD = 14

MAX_PACKET = 16384
MAX_PIXELS = 1 << 24
MAX_POIS = 65536
# SPEC's constants, named as the spec core (spec/include/pxflow_spec) names them without its
# PXFLOW_ (the ctest spec_copies checks every one against the core).
STATUS_DROPPED, STATUS_REJECTED, STATUS_ACCEPTED = 0, 1, 2
DIR_NONE = 8  # the integer match won the half-pixel vote
STEP_X = (1, 1, 0, -1, -1, -1, 0, 1, 0)  # SPEC §3's half-pixel steps, direction 8 = integer
STEP_Y = (0, 1, 1, 1, 0, -1, -1, -1, 0)
TILE = 8
MIN_RADIUS, MAX_RADIUS = 1, 31
MIN_BLOCKS, MAX_BLOCKS = 1, 255
MAX_THRESHOLD = 65535
MAX_FRAME_SIDE = 16384
# SPEC §4's record: x, y, status, pad, feature, dx, dy, sad, dir, pad, sub[8], hx, hy.
RECORD_FORMAT = "<HHBBHbbHBB8Hbb"


def cobs_encode(data: bytes) -> bytes:
    out, block = bytearray(), bytearray()
    for i, b in enumerate(data):
        if b == 0:
            out += bytes([len(block) + 1]) + block
            block = bytearray()
            continue
        block.append(b)
        if len(block) == 254:
            out += b"\xff" + block
            block = bytearray()
            if i + 1 == len(data):
                return bytes(out)
    return bytes(out + bytes([len(block) + 1]) + block)


def cobs_decode(data: bytes):
    out, i = bytearray(), 0
    while i < len(data):
        code = data[i]
        i += 1
        if code == 0 or i + code - 1 > len(data):
            return None
        out += data[i:i + code - 1]
        i += code - 1
        if code != 0xFF and i < len(data):
            out.append(0)
    return bytes(out)


def frame(msg_type: int, seq: int, body: bytes) -> bytes:
    packet = bytes([msg_type, seq]) + body
    return cobs_encode(packet + struct.pack("<I", zlib.crc32(packet))) + b"\x00"


def grid_axis(side, s, b):
    lo, hi = s + 1, side - (s + 1) - TILE
    if hi <= lo:
        return []
    step = (hi - lo) // b + 1
    return list(range(lo, hi, step))


def feature(prev, x, y):
    q = prev[y + 2:y + 6, x + 2:x + 6]
    return int(np.abs(q[:-1, :] - q[1:, :]).sum() + np.abs(q[:, :-1] - q[:, 1:]).sum())


def half_sads(block, nxt, mx, my):
    """The eight half-pixel SADs around the match at (mx, my): floor averages, the diagonal
    from two horizontal averages (SPEC §3). Arrays are indexed [v + 1, u + 1]."""
    p = nxt[my - 1:my + 9, mx - 1:mx + 9]
    h = (p[:, :-1] + p[:, 1:]) >> 1  # h(u, v), u -1..7, v -1..8
    g = (p[:-1, :] + p[1:, :]) >> 1  # g(u, v), u -1..8, v -1..7
    d = (h[:-1, :] + h[1:, :]) >> 1  # d(u, v), u -1..7, v -1..7
    values = (h[1:9, 1:9], d[1:9, 1:9], g[1:9, 1:9], d[1:9, 0:8], h[1:9, 0:8], d[0:8, 0:8],
              g[0:8, 1:9], d[0:8, 1:9])
    return [int(np.abs(block - v).sum()) for v in values]


def record(prev, nxt, x, y, q):
    """SPEC §4's record as (x, y, status, feature, dx, dy, sad, dir, sub, hx, hy)."""
    s = q["S"]
    feat = feature(prev, x, y)
    if feat < q["FT"]:
        return (x, y, STATUS_DROPPED, feat, 0, 0, 0, DIR_NONE, [0] * 8, 0, 0)
    block = prev[y:y + 8, x:x + 8]
    window = nxt[y - s:y + s + 8, x - s:x + s + 8]
    sads = np.abs(sliding_window_view(window, (8, 8)) - block).sum(axis=(2, 3))
    first = int(np.argmin(sads))  # row-major: dy outer, dx inner; the first minimum wins ties
    by, bx = first // (2 * s + 1) - s, first % (2 * s + 1) - s
    best = int(sads.flat[first])
    if best >= q["VT"]:
        return (x, y, STATUS_REJECTED, feat, bx, by, best, DIR_NONE, [0] * 8, 0, 0)
    sub = half_sads(block, nxt, x + bx, y + by)
    direction, least = DIR_NONE, best
    for k in range(8):
        if sub[k] < least:  # strictly better only: ties keep the lower k, and the integer match
            direction, least = k, sub[k]
    return (x, y, STATUS_ACCEPTED, feat, bx, by, best, direction, sub, 2 * bx + STEP_X[direction],
            2 * by + STEP_Y[direction])


def pack_record(r):
    x, y, status, feat, dx, dy, sad, direction, sub, hx, hy = r
    return struct.pack(RECORD_FORMAT, x, y, status, 0, feat, dx, dy, sad, direction, 0, *sub, hx, hy)


def estimate(records, q):
    """SPEC §5 in float32, one numpy float32 operation per firmware float operation."""
    s, f32 = q["S"], np.float32
    nbins = 2 * (2 * s + 1) + 1
    accepted = [r for r in records if r[2] == STATUS_ACCEPTED]
    count = len(accepted)
    if count <= q["MINCOUNT"]:
        return f32(0), f32(0), 0, count

    def filtered(values):
        hist = [0] * nbins
        for v in values:
            hist[v + 2 * s + 1] += 1
        peak = max(range(nbins), key=lambda b: (hist[b], -b))  # the first maximum
        value, weight = f32(0), f32(0)
        for b in range(max(peak - 2, 0), min(peak + 2, nbins - 1) + 1):
            value = f32(value + f32(b * hist[b]))
            weight = f32(weight + f32(hist[b]))
        return f32(f32(f32(value / weight) - f32(2 * s + 1)) / f32(2))

    hxs, hys = [r[9] for r in accepted], [r[10] for r in accepted]
    if q["HF"]:
        fx, fy = filtered(hxs), filtered(hys)
    else:
        fx = f32(f32(f32(sum(hxs)) / f32(2)) / f32(count))
        fy = f32(f32(f32(sum(hys)) / f32(2)) / f32(count))
    return fx, fy, count * 255 // (q["B"] * q["B"]), count


class Device:
    def __init__(self):
        self.q = None
        self.frames = [None, None]
        self.records = None
        self.last = None  # (seq, crc) of the last request executed
        self.reply = b""

    def send(self, data):
        os.write(1, data)

    def answer(self, msg_type, seq, body=b""):
        self.reply = frame(msg_type, seq, body)
        self.send(self.reply)

    def error(self, seq, code, text):
        self.answer(MSG_ERROR, seq, struct.pack("<HB", code, len(text)) + text.encode())

    def on_frame(self, raw):
        if not raw:
            return
        if len(raw) > MAX_PACKET + MAX_PACKET // 254 + 1:
            return self.send(frame(MSG_NAK, 0, bytes([NAK_TOO_LONG])))
        packet = cobs_decode(raw)
        if packet is None:
            return self.send(frame(MSG_NAK, 0, bytes([NAK_BAD_COBS])))
        if len(packet) < PACKET_OVERHEAD:
            return self.send(frame(MSG_NAK, 0, bytes([NAK_TOO_SHORT])))
        (crc,) = struct.unpack("<I", packet[-4:])
        if zlib.crc32(packet[:-4]) != crc:
            return self.send(frame(MSG_NAK, 0, bytes([NAK_BAD_CRC])))
        msg_type, seq, body = packet[0], packet[1], packet[2:-4]
        if msg_type != MSG_HELLO and self.last == (seq, crc):
            return self.send(self.reply)  # its reply was lost: the same reply again
        self.last = (seq, crc)
        handler = {MSG_HELLO: self.hello, MSG_PARAMS: self.params, MSG_FRAME: self.frame,
                   MSG_RUN: self.run, MSG_RECORDS: self.get_records}.get(msg_type)
        if handler is None:
            return self.error(seq, ERR_BAD_MESSAGE, "unknown message type")
        handler(seq, body)

    def hello(self, seq, body):
        strings = b"".join(bytes([len(s)]) + s for s in (
            b"numpy-prototype", b"tests/dut/pxdut_numpy.py", b"dut-python-perf-counter-ns"))
        self.answer(MSG_HELLO_REPLY, seq, struct.pack(
            "<HHIHHII", PROTOCOL_VERSION, HELLO_FLAG_ESTIMATE, 10**9, MAX_PACKET, 0, MAX_PIXELS,
            MAX_POIS) + strings)

    def params(self, seq, body):
        self.q, self.records = None, None
        if len(body) != PARAMS_BODY:
            return self.error(seq, ERR_BAD_MESSAGE, "PARAMS body is 10 x u32")
        w, h, s, t, b, ft, vt, hf, mc, gc = struct.unpack("<10I", body)
        if (t != TILE or gc != 0 or not MIN_RADIUS <= s <= MAX_RADIUS
                or not MIN_BLOCKS <= b <= MAX_BLOCKS or hf > 1
                or max(ft, vt, mc) > MAX_THRESHOLD or max(w, h) > MAX_FRAME_SIDE):
            return self.error(seq, ERR_BAD_PARAMS, "a parameter is outside SPEC's limits")
        nx, ny = grid_axis(w, s, b), grid_axis(h, s, b)
        if not nx or not ny:
            return self.error(seq, ERR_BAD_PARAMS, "the grid does not fit the frame")
        if w * h > MAX_PIXELS or len(nx) * len(ny) > MAX_POIS:
            return self.error(seq, ERR_TOO_LARGE, "too large for this device")
        self.q = dict(W=w, H=h, S=s, B=b, FT=ft, VT=vt, HF=hf, MINCOUNT=mc, xs=nx, ys=ny)
        self.frames = [np.zeros(w * h, np.int32), np.zeros(w * h, np.int32)]
        self.answer(MSG_ACK, seq)

    def frame(self, seq, body):
        if len(body) <= FRAME_HEADER or body[0] > 1:
            return self.error(seq, ERR_BAD_MESSAGE, "FRAME body is image, 0, 0, offset, bytes")
        if self.q is None:
            return self.error(seq, ERR_NOT_READY, "no PARAMS yet")
        (offset,) = struct.unpack("<I", body[4:8])
        data = np.frombuffer(body[FRAME_HEADER:], np.uint8)
        if offset + len(data) > self.q["W"] * self.q["H"]:
            return self.error(seq, ERR_RANGE, "FRAME bytes outside W*H")
        self.frames[body[0]][offset:offset + len(data)] = data
        self.records = None
        self.answer(MSG_ACK, seq)

    def run(self, seq, body):
        if len(body) != RUN_BODY:
            return self.error(seq, ERR_BAD_MESSAGE, "RUN body is u32 repetitions, u32 warmups")
        if self.q is None:
            return self.error(seq, ERR_NOT_READY, "no PARAMS yet")
        reps, warmups = struct.unpack("<II", body)
        if reps < 1:
            return self.error(seq, ERR_BAD_MESSAGE, "RUN needs at least 1 repetition")
        q = self.q
        prev = self.frames[0].reshape(q["H"], q["W"])
        nxt = self.frames[1].reshape(q["H"], q["W"])
        total, fastest = 0, 0xFFFFFFFF
        for i in range(warmups + reps):
            t0 = time.perf_counter_ns()
            records = [record(prev, nxt, x, y, q) for y in q["ys"] for x in q["xs"]]
            fx, fy, quality, count = estimate(records, q)
            ticks = (time.perf_counter_ns() - t0) & 0xFFFFFFFF
            if i >= warmups:
                total, fastest = total + ticks, min(fastest, ticks)
        self.records = records
        self.answer(MSG_RESULT, seq, struct.pack("<IIQII", len(records), reps, total, fastest,
                                                 RESULT_FLAG_ESTIMATE) +
                    fx.tobytes() + fy.tobytes() + struct.pack("<ii", quality, count))

    def get_records(self, seq, body):
        if len(body) != RECORDS_BODY:
            return self.error(seq, ERR_BAD_MESSAGE, "RECORDS body is u32 first, u32 count")
        if self.records is None:
            return self.error(seq, ERR_NOT_READY, "no RUN since the last PARAMS or FRAME")
        first, count = struct.unpack("<II", body)
        if count < 1 or count > (MAX_PACKET - RECORDS_REPLY_OVERHEAD) // RECORD_BYTES or first + count > len(self.records):
            return self.error(seq, ERR_RANGE, "RECORDS range outside the run's records or reply size")
        self.answer(MSG_RECORDS_REPLY, seq, struct.pack("<II", first, count) + b"".join(
            pack_record(r) for r in self.records[first:first + count]))


def main():
    device, pending = Device(), bytearray()
    while True:
        chunk = os.read(0, 65536)
        if not chunk:
            return 0  # the host closed the link
        pending += chunk
        while True:
            end = pending.find(b"\x00")
            if end < 0:
                break
            raw = bytes(pending[:end])
            del pending[:end + 1]
            device.on_frame(raw)


if __name__ == "__main__":
    sys.exit(main())
