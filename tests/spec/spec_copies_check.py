#!/usr/bin/env python3
"""SPEC's constants are written once, in the freestanding spec core (spec/include/pxflow_spec).
What cannot include it is checked against it here: the OpenCL kernel (.cl), the Vulkan shader
(.comp) and the Python device (.py) each name the status codes, the direction code and the
half-pixel step table as the core does (without PXFLOW_; GLSL and OpenCL spell them kStepX,
kStatusDropped, DIR_NONE ...), with the core's values; the Python device also names the limits it
checks and the record layout.
usage: spec_copies_check.py SPEC_INCLUDE_DIR COPY...; one line per disagreement, exit 1.
"""
import glob
import os
import re
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from python_constants import python_constants  # noqa: E402

# What every copy must name, and what the Python device names besides.
EVERY_COPY = ["STATUS_DROPPED", "STATUS_REJECTED", "STATUS_ACCEPTED", "DIR_NONE", "STEP_X",
              "STEP_Y"]
PYTHON_ALSO = ["TILE", "MIN_RADIUS", "MAX_RADIUS", "MIN_BLOCKS", "MAX_BLOCKS", "MAX_THRESHOLD",
               "MAX_FRAME_SIDE", "RECORD_BYTES"]
# SPEC §4's fields in order as a struct format lays them out (pads unnamed).
RECORD_FIELDS = ["X", "Y", "STATUS", None, "FEATURE", "DX", "DY", "SAD", "DIR", None] + \
    ["SUB"] * 8 + ["HX", "HY"]


def core_constants(include_dir):
    """NAME (without PXFLOW_) -> int or tuple, from every literal #define of the core."""
    table = {}
    for path in sorted(glob.glob(os.path.join(include_dir, "pxflow_spec", "*.h"))):
        text = open(path, encoding="utf-8").read().replace("\\\n", " ")  # continuation lines
        for m in re.finditer(r"^#define\s+PXFLOW_(\w+)\s+(0x[0-9A-Fa-f]+|\d+)u\b", text, re.M):
            table[m.group(1)] = int(m.group(2), 0)
        for m in re.finditer(r"^#define\s+PXFLOW_(\w+)_TABLE\s+\{([-\d,\s]+)\}", text, re.M):
            table[m.group(1)] = tuple(int(v) for v in m.group(2).split(","))
    return table


def snake(name):
    """kStatusDropped -> STATUS_DROPPED, kStepX -> STEP_X, DIR_NONE -> DIR_NONE."""
    if re.match(r"k[A-Z]", name):
        name = re.sub(r"(?<!^)([A-Z])", r"_\1", name[1:])
    return name.upper()


def c_like_constants(path):
    """NAME -> value of #defines, `const` scalars and initialised arrays (OpenCL C, GLSL)."""
    text, out = open(path, encoding="utf-8").read(), {}
    for m in re.finditer(r"#define\s+(\w+)\s+(-?\d+)u?\b", text):
        out[snake(m.group(1))] = int(m.group(2))
    for m in re.finditer(r"\bconst\s+(?:u?int)\s+(\w+)\s*=\s*(-?\d+)u?\s*;", text):
        out[snake(m.group(1))] = int(m.group(2))
    for m in re.finditer(r"\b(\w+)\[\d*\]\s*=\s*(?:int\[\d*\])?[({]([-\d,\s]+)[)}]", text):
        out[snake(m.group(1))] = tuple(int(v) for v in m.group(2).split(","))
    return out


def record_offsets(fmt):
    """Offsets of SPEC §4's named fields in a struct format such as "<HHBBHbbHBB8Hbb"."""
    codes = []
    for count, code in re.findall(r"(\d*)([a-zA-Z])", fmt):
        codes += [code] * int(count or 1)
    if len(codes) != len(RECORD_FIELDS):
        return None
    offsets = {}
    for k, name in enumerate(RECORD_FIELDS):
        if name and name not in offsets:
            offsets[name] = struct.calcsize(fmt[0] + "".join(codes[:k]))
    return offsets


def check(path, core):
    python = path.endswith(".py")
    got = python_constants(path) if python else c_like_constants(path)
    problems = []
    for name in EVERY_COPY + (PYTHON_ALSO if python else []):
        if name not in got:
            problems.append(f"{path}: no {name} (the spec core's PXFLOW_{name})")
        elif got[name] != core[name]:
            problems.append(f"{path}: {name} is {got[name]}, the spec core's PXFLOW_{name} is "
                            f"{core[name]}")
    if python:
        offsets = record_offsets(got.get("RECORD_FORMAT") or "")
        if offsets is None:
            problems.append(f"{path}: RECORD_FORMAT does not have SPEC §4's fields")
        else:
            for name, at in offsets.items():
                if at != core["RECORD_AT_" + name]:
                    problems.append(f"{path}: RECORD_FORMAT puts {name.lower()} at byte {at}, "
                                    f"the spec core at {core['RECORD_AT_' + name]}")
    # Written once per copy: the table's values appear nowhere else in the file.
    text = open(path, encoding="utf-8").read()
    for name in ("STEP_X", "STEP_Y"):
        spelled = r",\s*".join(str(v) for v in core[name])
        if len(re.findall(spelled, text)) > 1:
            problems.append(f"{path}: {name}'s values are written more than once")
    return problems


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    core = core_constants(argv[1])
    missing = [n for n in EVERY_COPY + PYTHON_ALSO if n not in core]
    problems = [f"{argv[1]}: the spec core has no PXFLOW_{n}" for n in missing]
    if not missing:
        for path in argv[2:]:
            problems += check(path, core)
    for p in problems:
        print(p)
    print(f"{len(core)} constants in the spec core, {len(argv) - 2} copies; "
          f"{len(problems)} disagreements")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
