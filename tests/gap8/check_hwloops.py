#!/usr/bin/env python3
"""Checks every RI5CY hardware loop in GAP8 kernel ELFs against the documented constraints.

Usage: check_hwloops.py OBJDUMP ELF...   (exit 0: all loops legal, 1: a violation, 2: bad input)

The loops are found by their set-up instructions (opcode 0x7B: lp.setup, lp.setupi, and
lp.starti/lp.endi pairs), decoded as the model decodes them (gap8_model/src/decode_xpulp.cpp:
end = the loop's last instruction). Rules, from the RI5CY user manual (rev. 4.4, "PULP Hardware
Loop Extensions") and, where stricter, the CV32E40P user manual ("Hardware Loop constraints"):
  - the body's first instruction and the set-up instructions are word-aligned;
  - the body has at least 3 instructions, none of them compressed;
  - no branch or jump anywhere in the body (CV32E40P; RI5CY forbids it as the last one);
  - a loop 1 that contains a loop 0 ends at least 2 instructions (8 bytes) after it.
"""
import re
import subprocess
import sys

BRANCH_OPCODES = {0x63: "branch", 0x6F: "jal", 0x67: "jalr"}


def instructions(objdump, elf):
    out = subprocess.run([objdump, "-d", elf], capture_output=True, text=True, check=True).stdout
    found = {}
    for line in out.splitlines():
        m = re.match(r"\s*([0-9a-f]+):\s+([0-9a-f]{4}|[0-9a-f]{8})\s", line)
        if m:
            found[int(m.group(1), 16)] = (int(m.group(2), 16), len(m.group(2)) // 2)
    return found


def loops(code):
    """(set-up address, loop number, first body address, last body address) of every loop."""
    result, open_starts = [], {}
    for addr in sorted(code):
        word, size = code[addr]
        if size != 4 or (word & 0x7F) != 0x7B:
            continue
        f3, loop = (word >> 12) & 7, (word >> 7) & 1
        imm, rs1 = (word >> 20) & 0xFFF, (word >> 15) & 31
        if f3 == 4:  # lp.setup L, rs1, end: body at pc + 4
            result.append((addr, loop, addr + 4, addr + 2 * imm))
        elif f3 == 5:  # lp.setupi L, count, end: end in the rs1 field
            result.append((addr, loop, addr + 4, addr + 2 * rs1))
        elif f3 == 0:  # lp.starti
            open_starts[loop] = (addr, addr + 2 * imm)
        elif f3 == 1 and loop in open_starts:  # lp.endi, after its lp.starti
            setup, start = open_starts.pop(loop)
            result.append((setup, loop, start, addr + 2 * imm))
    return result


def violations(code, found):
    problems = []
    for setup, loop, start, end in found:
        where = "loop %d set up at 0x%x" % (loop, setup)
        body = [a for a in sorted(code) if start <= a <= end]
        if setup % 4 or start % 4:
            problems.append(where + ": not word-aligned")
        if len(body) < 3:
            problems.append(where + ": body of %d instructions" % len(body))
        for a in body:
            word, size = code[a]
            if size != 4:
                problems.append(where + ": compressed instruction at 0x%x" % a)
            elif (word & 0x7F) in BRANCH_OPCODES:
                problems.append(where + ": %s at 0x%x" % (BRANCH_OPCODES[word & 0x7F], a))
        if loop == 1:
            for _, inner, s0, e0 in found:
                if inner == 0 and start <= s0 <= end and end < e0 + 8:
                    problems.append(where + ": ends less than 8 bytes after loop 0 at 0x%x" % e0)
    return problems


def main(argv):
    if len(argv) < 3:
        print(__doc__.splitlines()[2], file=sys.stderr)
        return 2
    bad = 0
    for elf in argv[2:]:
        code = instructions(argv[1], elf)
        found = loops(code)
        problems = violations(code, found)
        for p in problems:
            print("%s: %s" % (elf, p))
        if not found:
            print("%s: no hardware loop found" % elf)
            problems.append("none")
        bad += len(problems)
        print("%s: %d hardware loops, %s" % (elf, len(found), "bad" if problems else "ok"))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
