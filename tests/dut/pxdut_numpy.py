#!/usr/bin/env python3
"""A device under test in Python and numpy: the worked example for prototyping a port before
writing C. It speaks docs/dut-protocol.md version 1 on stdin/stdout and implements SPEC.md
sections 2-5 with whole-array numpy operations (not the firmware's shape). Checked by
    pxflow check --dut py=exec:python3 tests/dut/pxdut_numpy.py --require py
Its own code throughout: COBS and the frame handling are written from the protocol page, and the
CRC is zlib's crc32 (CRC-32/ISO-HDLC, the protocol's CRC), a second implementation beside dut/'s.
"""
import os
import struct
import sys
import time
import zlib

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view

VERSION = 1
MAX_PACKET = 16384
MAX_PIXELS = 1 << 24
MAX_POIS = 65536
STEP_X = (1, 1, 0, -1, -1, -1, 0, 1, 0)  # SPEC §3's half-pixel steps, direction 8 = integer
STEP_Y = (0, 1, 1, 1, 0, -1, -1, -1, 0)


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
    lo, hi = s + 1, side - (s + 1) - 8
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
        return (x, y, 0, feat, 0, 0, 0, 8, [0] * 8, 0, 0)
    block = prev[y:y + 8, x:x + 8]
    window = nxt[y - s:y + s + 8, x - s:x + s + 8]
    sads = np.abs(sliding_window_view(window, (8, 8)) - block).sum(axis=(2, 3))
    first = int(np.argmin(sads))  # row-major: dy outer, dx inner; the first minimum wins ties
    by, bx = first // (2 * s + 1) - s, first % (2 * s + 1) - s
    best = int(sads.flat[first])
    if best >= q["VT"]:
        return (x, y, 1, feat, bx, by, best, 8, [0] * 8, 0, 0)
    sub = half_sads(block, nxt, x + bx, y + by)
    direction, least = 8, best
    for k in range(8):
        if sub[k] < least:  # strictly better only: ties keep the lower k, and the integer match
            direction, least = k, sub[k]
    return (x, y, 2, feat, bx, by, best, direction, sub, 2 * bx + STEP_X[direction],
            2 * by + STEP_Y[direction])


def pack_record(r):
    x, y, status, feat, dx, dy, sad, direction, sub, hx, hy = r
    return struct.pack("<HHBBHbbHBB8Hbb", x, y, status, 0, feat, dx, dy, sad, direction, 0, *sub,
                       hx, hy)


def estimate(records, q):
    """SPEC §5 in float32, one numpy float32 operation per firmware float operation."""
    s, f32 = q["S"], np.float32
    nbins = 2 * (2 * s + 1) + 1
    accepted = [r for r in records if r[2] == 2]
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
        self.answer(0x7F, seq, struct.pack("<HB", code, len(text)) + text.encode())

    def on_frame(self, raw):
        if not raw:
            return
        if len(raw) > MAX_PACKET + MAX_PACKET // 254 + 1:
            return self.send(frame(0x15, 0, b"\x03"))
        packet = cobs_decode(raw)
        if packet is None:
            return self.send(frame(0x15, 0, b"\x02"))
        if len(packet) < 6:
            return self.send(frame(0x15, 0, b"\x04"))
        (crc,) = struct.unpack("<I", packet[-4:])
        if zlib.crc32(packet[:-4]) != crc:
            return self.send(frame(0x15, 0, b"\x01"))
        msg_type, seq, body = packet[0], packet[1], packet[2:-4]
        if msg_type != 0x01 and self.last == (seq, crc):
            return self.send(self.reply)  # its reply was lost: the same reply again
        self.last = (seq, crc)
        handler = {0x01: self.hello, 0x02: self.params, 0x03: self.frame, 0x04: self.run,
                   0x05: self.get_records}.get(msg_type)
        if handler is None:
            return self.error(seq, 1, "unknown message type")
        handler(seq, body)

    def hello(self, seq, body):
        strings = b"".join(bytes([len(s)]) + s for s in (
            b"numpy-prototype", b"tests/dut/pxdut_numpy.py", b"dut-python-perf-counter-ns"))
        self.answer(0x81, seq, struct.pack("<HHIHHII", VERSION, 1, 10**9, MAX_PACKET, 0,
                                           MAX_PIXELS, MAX_POIS) + strings)

    def params(self, seq, body):
        self.q, self.records = None, None
        if len(body) != 40:
            return self.error(seq, 1, "PARAMS body is 10 x u32")
        w, h, s, t, b, ft, vt, hf, mc, gc = struct.unpack("<10I", body)
        if t != 8 or gc != 0 or not 1 <= s <= 31 or not 1 <= b <= 255:
            return self.error(seq, 2, "T must be 8, GC 0, S 1..31, B 1..255")
        nx, ny = grid_axis(w, s, b), grid_axis(h, s, b)
        if not nx or not ny:
            return self.error(seq, 2, "the grid does not fit the frame")
        if w * h > MAX_PIXELS or len(nx) * len(ny) > MAX_POIS:
            return self.error(seq, 3, "too large for this device")
        self.q = dict(W=w, H=h, S=s, B=b, FT=ft, VT=vt, HF=hf, MINCOUNT=mc, xs=nx, ys=ny)
        self.frames = [np.zeros(w * h, np.int32), np.zeros(w * h, np.int32)]
        self.answer(0x06, seq)

    def frame(self, seq, body):
        if len(body) < 9 or body[0] > 1:
            return self.error(seq, 1, "FRAME body is image, 0, 0, offset, bytes")
        if self.q is None:
            return self.error(seq, 4, "no PARAMS yet")
        (offset,) = struct.unpack("<I", body[4:8])
        data = np.frombuffer(body[8:], np.uint8)
        if offset + len(data) > self.q["W"] * self.q["H"]:
            return self.error(seq, 5, "FRAME bytes outside W*H")
        self.frames[body[0]][offset:offset + len(data)] = data
        self.records = None
        self.answer(0x06, seq)

    def run(self, seq, body):
        if len(body) != 8:
            return self.error(seq, 1, "RUN body is u32 repetitions, u32 warmups")
        if self.q is None:
            return self.error(seq, 4, "no PARAMS yet")
        reps, warmups = struct.unpack("<II", body)
        if reps < 1:
            return self.error(seq, 1, "RUN needs at least 1 repetition")
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
        self.answer(0x84, seq, struct.pack("<IIQII", len(records), reps, total, fastest, 1) +
                    fx.tobytes() + fy.tobytes() + struct.pack("<ii", quality, count))

    def get_records(self, seq, body):
        if len(body) != 8:
            return self.error(seq, 1, "RECORDS body is u32 first, u32 count")
        if self.records is None:
            return self.error(seq, 4, "no RUN since the last PARAMS or FRAME")
        first, count = struct.unpack("<II", body)
        if count < 1 or count > (MAX_PACKET - 14) // 32 or first + count > len(self.records):
            return self.error(seq, 5, "RECORDS range outside the run's records or reply size")
        self.answer(0x85, seq, struct.pack("<II", first, count) + b"".join(
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
