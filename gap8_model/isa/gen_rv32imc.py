#!/usr/bin/env python3
"""Generates the GAP8 model's RV32IMC decoder rows and dispatch from rv32imc.tbl.

  gen_rv32imc.py TABLE OUTDIR   writes OUTDIR/gap8/rv32imc_{ops,decode,execute}.inc

ops: the Op enum entries in the table's order; decode: one row per instruction (the decoder
takes the first that fits, src/decode.cpp); execute: Core::Execute's cases by class and
semantics. Refuses (exit 2, one line) a bad table.
"""
import os
import sys

import gen_xpulp
import isa_format

CLASSES = {"alu", "load", "store", "branch", "jump", "muldiv"}
# An RVC register token: the Decoded slots it fills (32-bit rows take rd, rs1, rs2 as they are).
RVC_SLOTS = {
    "crd": ("rd",), "crd+": ("rd", "rs1"), "crs1": ("rs1",), "crs2": ("rs2",),
    "crd'": ("rd",), "crs2'": ("rs2",), "crs1'": ("rs1",), "crs1'+": ("rd", "rs1"),
    "sp": ("rs1",), "sp+": ("rd", "rs1"), "^ra": ("rd",),
}
IMMEDIATES = {  # format token -> RvImm (src/decode_fields.h)
    "u20": "kU20", "jt": "kJ", "bt": "kB", "i12": "kI", "s12": "kS", "shamt": "kShamt",
    "ci6": "kCi6", "cshamt": "kCShamt", "clui": "kCLui", "c16sp": "kC16sp", "c4spn": "kC4spn",
    "clw": "kClw", "clwsp": "kClwsp", "cswsp": "kCswsp", "cj": "kCj", "cb": "kCb",
}


class TableError(Exception):
    pass


def parse(path):
    rows = []
    try:
        for number, cols in isa_format.table_rows(path, 7):
            mn, match, mask, op, fmt, cls, sem = cols
            r = dict(mnemonic=mn, match=int(match, 16), mask=int(mask, 16), op=op, fmt=fmt,
                     cls=cls, sem=sem, size=2 if int(match, 16) & 3 != 3 else 4, line=number)
            check_row(path, r)
            rows.append(r)
    except isa_format.FormatError as e:
        raise TableError(str(e)) from e
    seen = {}
    for r in rows:
        first = seen.setdefault(r["op"], r)
        if first is not r and (r["sem"] != "-" or first["cls"] != r["cls"]):
            raise TableError(f"{path}:{r['line']}: {r['mnemonic']}: a later row of op {r['op']} "
                             f"must have its class and semantics -")
        if first is r and r["op"] != "Illegal" and (
                (r["cls"] in ("alu", "branch")) == (r["sem"] == "-")):
            raise TableError(f"{path}:{r['line']}: {r['mnemonic']}: the first row of an alu "
                             f"or branch op has semantics, the others -")
    return rows


def check_row(path, r):
    where = f"{path}:{r['line']}: {r['mnemonic']}"
    if r["match"] & ~r["mask"]:
        raise TableError(f"{where}: match has bits outside the mask")
    if r["mask"] & 3 != 3 or (r["size"] == 2 and r["mask"] >= 0x10000):
        raise TableError(f"{where}: the mask must cover bits 1..0 (a 16-bit parcel's below "
                         f"0x10000)")
    if r["cls"] not in CLASSES:
        raise TableError(f"{where}: unknown class {r['cls']}")
    isa_format.check(r["fmt"])
    imms = [t for t in isa_format.tokens(r["fmt"]) if t in isa_format.IMMEDIATES]
    if len([t for t in imms if t in IMMEDIATES]) > 1:
        raise TableError(f"{where}: more than one immediate")
    if r["size"] == 2:
        for t in isa_format.tokens(r["fmt"]):
            if t in isa_format.REGISTERS and t not in RVC_SLOTS:
                raise TableError(f"{where}: {t} is no RVC register token")


def ops_in_order(rows):
    ops = {}
    for r in rows:
        if r["op"] != "Illegal":
            ops.setdefault(r["op"], r)
    return ops


def gen_ops(rows):
    return "".join(f"GAP8_RV32IMC_OP({op})\n" for op in ops_in_order(rows))


def decode_row(r):
    toks = isa_format.tokens(r["fmt"])
    reads, writes = isa_format.reads_writes(r["fmt"])
    slots = {"rd": "kNoField", "rs1": "kNoField", "rs2": "kNoField"}
    if r["size"] == 4:  # the 32-bit formats' fields as they are; rd only when written
        slots = {"rd": "kRd" if "rd" in writes else "kNoField", "rs1": "kRs1", "rs2": "kRs2"}
    else:
        for t in toks:
            field = isa_format.REGISTERS.get(t, (None,))[0]
            for slot in RVC_SLOTS.get(t, ()):
                slots[slot] = "k" + "".join(p.capitalize() for p in field.split("_"))
    imm = next((IMMEDIATES[t] for t in toks if t in IMMEDIATES), "kNone")
    width = -1 if r["cls"] in ("load", "store") and r["size"] == 4 else (
        2 if r["cls"] in ("load", "store") else 0)
    return (f"{{0x{r['match']:08x}u, 0x{r['mask']:08x}u, Op::k{r['op']}, {r['size']}, "
            f"RvImm::{imm}, {width}, {slots['rd']}, {slots['rs1']}, {slots['rs2']}, "
            f"{isa_format.field_bits(reads)}}},  // {r['mnemonic']}\n")


def gen_decode(rows):
    return "".join(decode_row(r) for r in rows)


def gen_execute(rows):
    """Case labels of Core::ExecuteInline's switch (a, b: rs1 and rs2 values; imm: d.imm)."""
    out, groups = [], {"memory": [], "muldiv": [], "jump": []}
    for op, r in ops_in_order(rows).items():
        if r["cls"] == "alu":
            out.append(f"case Op::k{op}:\n  result = {r['sem']};\n  break;\n")
        elif r["cls"] == "branch":
            out.append(f"case Op::k{op}:\n  return ExecuteBranch(d, {r['sem']});\n")
        else:
            groups["memory" if r["cls"] in ("load", "store") else r["cls"]].append(op)
    tails = {"memory": "return ExecuteMemory(d);", "muldiv": "return ExecuteMulDiv(d);", "jump": "return ExecuteJump(d, a, imm);"}
    for group, members in groups.items():
        if members:
            out.append("".join(f"case Op::k{op}:\n" for op in members) + f"  {tails[group]}\n")
    return "".join(out)


WRITERS = {"rv32imc_ops.inc": gen_ops, "rv32imc_decode.inc": gen_decode,
           "rv32imc_execute.inc": gen_execute}


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        rows = parse(argv[1])
        for name, writer in WRITERS.items():
            text = "// Generated by gap8_model/isa/gen_rv32imc.py from rv32imc.tbl: do not edit.\n"
            gen_xpulp.write_if_changed(os.path.join(argv[2], "gap8", name), text + writer(rows))
    except (TableError, isa_format.FormatError, OSError, ValueError) as e:
        print(f"gen_rv32imc: error: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
