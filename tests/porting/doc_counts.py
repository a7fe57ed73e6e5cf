#!/usr/bin/env python3
"""Counts the docs quote from pxflow's output are this tree's: each row of FACTS names a page, the
sentence's pattern (its groups are the numbers), the pxflow command whose --json gives them and
the fields. A page whose numbers differ fails with the command to rerun; a row whose backend
cannot run here is skipped (exit 77 when any was and none failed).
Usage: doc_counts.py SOURCE_DIR PXFLOW"""
import json
import os
import re
import subprocess
import sys
import tempfile

# (page, pattern, pxflow arguments, row, fields of the row's outcome in the check file)
FACTS = [
    ("docs/cortex-m4.md", r"\*\*(\d+)\s+cases,\s+(\d+)\s+pairs\s+passed,\s+(\d+)\s+n/a",
     ["check", "--backends", "ref-original,m4-qemu", "--require", "m4-qemu"], "m4-qemu",
     ["passed", "pairs", "not_applicable"]),
]


def available(pxflow, row):
    out = subprocess.run([pxflow, "backends"], capture_output=True, text=True).stdout
    return any(line.split()[:2] == [row, "available"] for line in out.splitlines())


def main():
    source, pxflow = sys.argv[1], sys.argv[2]
    failed = skipped = 0
    for page, pattern, args, row, fields in FACTS:
        text = open(os.path.join(source, page)).read()
        found = re.search(pattern, text, re.S)
        if not found:
            print("FAIL %s: no sentence matches %r" % (page, pattern))
            failed += 1
            continue
        where = "%s:%d" % (page, text.count("\n", 0, found.start()) + 1)
        if not available(pxflow, row):
            print("skip %s (backend %s cannot run here)" % (where, row))
            skipped += 1
            continue
        with tempfile.TemporaryDirectory() as tmp:
            result = os.path.join(tmp, "check.json")
            run = subprocess.run([pxflow] + args + ["--json", result], capture_output=True, text=True)
            if run.returncode != 0:
                print("FAIL %s: `pxflow %s` exit %d:\n%s" % (where, " ".join(args), run.returncode,
                                                          run.stdout[-2000:] + run.stderr[-2000:]))
                failed += 1
                continue
            outcome = [b for b in json.load(open(result))["backends"] if b["backend"] == row][0]
        doc = [int(n) for n in found.groups()]
        now = [outcome[f] for f in fields]
        if doc != now:
            print("FAIL %s says %s = %s; `build/pxflow %s` gives %s: update the page" %
                  (where, ", ".join(fields), doc, " ".join(args), now))
            failed += 1
        else:
            print("ok   %s: %s = %s" % (where, ", ".join(fields), now))
    if failed:
        return 1
    return 77 if skipped else 0


if __name__ == "__main__":
    sys.exit(main())
