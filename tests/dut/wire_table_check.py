#!/usr/bin/env python3
"""The protocol's numbers are written once, in dut/include/pxdut_wire.h. What cannot include the
header is checked against it here: the Python device's constants (tests/dut/pxdut_numpy.py, which
stays a standalone file to copy) and docs/dut-protocol.md's tables and quoted sizes.
usage: wire_table_check.py HEADER PYTHON_DEVICE PROTOCOL_PAGE; one line per disagreement, exit 1.
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from python_constants import python_constants  # noqa: E402


def header_constants(path):
    """PXDUT_NAME -> value of every #define but the include guard; each must be a plain literal."""
    table, problems = {}, []
    for n, line in enumerate(open(path, encoding="utf-8"), 1):
        m = re.match(r"#define\s+(PXDUT_\w+)(.*)", line)
        if not m or m.group(1) == "PXDUT_WIRE_H":
            continue
        value = re.match(r"\s+(0x[0-9A-Fa-f]+|\d+)u\b", m.group(2))
        if not value:
            problems.append(f"{path}:{n}: {m.group(1)} is not a plain unsigned literal")
            continue
        table[m.group(1)] = int(value.group(1), 0)
    return table, problems


def int_constants(path):
    """NAME -> value of the module's top-level integer constants."""
    return {k: v for k, v in python_constants(path).items() if isinstance(v, int)}


def check_python(path, table):
    problems = []
    consts = int_constants(path)
    for name, value in consts.items():
        full = "PXDUT_" + name
        if full in table and table[full] != value:
            problems.append(f"{path}: {name} = {value:#x}, {full} is {table[full]:#x}")
        elif full not in table and re.match(r"(MSG|NAK|ERR)_", name):
            problems.append(f"{path}: {name} has no {full} in the header")
    for full in table:  # a device must know every message and NAK reason
        if re.match(r"PXDUT_(MSG|NAK)_", full) and full[6:] not in consts:
            problems.append(f"{path}: no {full[6:]} (the header's {full})")
    # The constants must be what the device uses: no message type, NAK or ERROR code written bare.
    source = open(path, encoding="utf-8").read()
    for bare in re.finditer(r"(answer\(|frame\(|self\.error\(seq, )(0x[0-9A-Fa-f]+|\d+)", source):
        line = source.count("\n", 0, bare.start()) + 1
        problems.append(f"{path}:{line}: a bare code {bare.group(2)}: use the header's name")
    return problems


# Sizes the page quotes in its text: (pattern, header names of its groups in order).
QUOTED = [
    (r"\*\*Protocol version: (\d+)\.\*\*", ["PXDUT_PROTOCOL_VERSION"]),
    (r"packet shorter than (\d+) bytes", ["PXDUT_PACKET_OVERHEAD"]),
    (r"decoded, at least (\d+)\)", ["PXDUT_MAX_PACKET_MIN"]),
    (r"host accepts packets up to ([\d,]+) bytes", ["PXDUT_MAX_PACKET_MAX"]),
    (r"chunks of at most `max_packet - (\d+)` bytes", ["PXDUT_FRAME_CHUNK_MARGIN"]),
    (r"`\(max_packet - (\d+)\) / (\d+)` records",
     ["PXDUT_RECORDS_REPLY_OVERHEAD", "PXDUT_RECORD_BYTES"]),
    (r"\*\*Record layout\*\* \((\d+) bytes", ["PXDUT_RECORD_BYTES"]),
]


def check_page(path, table):
    problems, named = [], set()
    text = open(path, encoding="utf-8").read()
    # Table rows: | value | `PXDUT_NAME` | ...
    for m in re.finditer(r"^\| (0x[0-9A-Fa-f]+|\d+) \|(?: [^|]+ \|)? `(PXDUT_\w+)` \|", text, re.M):
        value, name = int(m.group(1), 0), m.group(2)
        named.add(name)
        if name not in table:
            problems.append(f"{path}: the table names {name}, which the header lacks")
        elif table[name] != value:
            shown = hex(table[name]) if m.group(1).startswith("0x") else table[name]
            problems.append(f"{path}: the table says {name} is {m.group(1)}, the header {shown}")
    # Flags: bit N (`PXDUT_NAME`)
    for m in re.finditer(r"bit (\d+) \(`(PXDUT_\w+)`\)", text):
        named.add(m.group(2))
        if table.get(m.group(2)) != 1 << int(m.group(1)):
            problems.append(f"{path}: bit {m.group(1)} is not the header's {m.group(2)}")
    for name in table:
        if re.match(r"PXDUT_(MSG|NAK|ERR)_|PXDUT_\w+_FLAG_", name) and name not in named:
            problems.append(f"{path}: no table row names the header's {name}")
    for pattern, names in QUOTED:
        found = re.findall(pattern, text)
        if not found:
            problems.append(f"{path}: the text no longer says /{pattern}/ (update this check)")
        for groups in found:
            groups = groups if isinstance(groups, tuple) else (groups,)
            for got, name in zip(groups, names):
                if int(got.replace(",", "")) != table[name]:
                    problems.append(f"{path}: the text says {got} where the header's {name} is "
                                    f"{table[name]}")
    return problems


def main(argv):
    if len(argv) != 4:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    table, problems = header_constants(argv[1])
    problems += check_python(argv[2], table)
    problems += check_page(argv[3], table)
    for p in problems:
        print(p)
    print(f"{len(table)} constants in {argv[1]}; {len(problems)} disagreements")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
