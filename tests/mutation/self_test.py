"""mutate.py self-test: the tool cannot rot (ctest mutation_self_test). It never writes into the
source tree (other tests build from it at the same time): mutants are applied to copies in memory,
the end-to-end mutant is compiled from a temporary folder.

- every file of the table exists, has mutants, and each mutant applies and reverts exactly;
- every operator finds a site somewhere, every family of the table is used;
- every entry of equivalent.txt and undetectable.txt names a mutant the tool generates (a stale
  one fails);
- with --pxflow: every row of the table is a row of that binary (families not built excepted),
  and with --dut-ref the dut reference device is where the table runs it;
- with --cc: one mutant of the dut reference kernel, compiled in a temporary folder, differs from
  the unmutated object, and the trivial-equivalence digest ignores debug information.
"""

import json
import os
import shutil
import subprocess
import tempfile

import operators
import tce
from mutate import UNDETECTABLE, all_mutants, load_equivalents
from targets import FAMILIES, OPTION_ROWS, TARGETS

E2E_FILE = "dut/src/pxdut_kernel.c"


def check_mutants(source, problems):
    by_path = all_mutants(source)
    used_ops, total = set(), 0
    for path, (text, mutants) in by_path.items():
        if not mutants:
            problems.append(f"{path}: no mutant")
        for m in mutants:
            mutated = m.apply(text)
            if mutated == text:
                problems.append(f"{m.id}: the mutant changes nothing")
            if m.revert(mutated, text[m.start : m.end]) != text:
                problems.append(f"{m.id}: does not revert to the original")
            used_ops.add(m.op)
        total += len(mutants)
    for op in operators.OPERATORS:
        if op not in used_ops:
            problems.append(f"operator {op}: no site in any kernel file")
    for name in FAMILIES:
        if not any(t.family == name for t in TARGETS):
            problems.append(f"family {name}: no file in the table")
    ids = {m.id for _, ms in by_path.values() for m in ms}
    for name, listed in (("equivalent.txt", load_equivalents()),
                         ("undetectable.txt", load_equivalents(UNDETECTABLE))):
        for ident in listed:
            if ident not in ids:
                problems.append(f"{name}: {ident} is not a mutant of the tree (stale: update it)")
    return total


def check_rows(pxflow, problems):
    out = subprocess.run([pxflow, "backends", "--json", "-"], stdout=subprocess.PIPE, check=True).stdout
    rows = json.loads(out)["backends"]
    names = {r["backend"] for r in rows}
    built = {r["family"] for r in rows}
    for t in TARGETS:
        registry = FAMILIES[t.family].registry
        for row in t.rows:
            if row in OPTION_ROWS:
                continue
            if registry in built and row not in names:
                problems.append(f"{t.path}: row {row} is not a row of {pxflow} (pxflow backends)")


def check_dut_ref(pxflow, dut_ref, problems):
    """FAMILIES['dut'] runs {build}/pxflow-dut-ref: the device must be built beside pxflow."""
    build = os.path.dirname(os.path.abspath(pxflow))
    expected = [a.format(build=build) for a in FAMILIES["dut"].check_args][-1].split(":", 1)[1]
    if os.path.abspath(dut_ref) != expected:
        problems.append(f"the dut family runs {expected}, but the device is built as {dut_ref}")


def compile_object(cc, source, text, folder, name, flags):
    # One file name for all (the object's symbol table names its source file), one folder each.
    os.mkdir(os.path.join(folder, name))
    src = os.path.join(folder, name, "kernel.c")
    with open(src, "w") as f:
        f.write(text)
    obj = os.path.join(folder, name, "kernel.o")
    includes = [f"-I{os.path.join(source, d)}" for d in ("dut/include", "dut/src", "spec/include")]
    subprocess.run([cc, "-std=c99", "-O2", *flags, *includes, "-c", src, "-o", obj], check=True)
    return tce.digest(obj)


def check_end_to_end(cc, source, problems):
    with open(os.path.join(source, E2E_FILE)) as f:
        text = f.read()
    mutant = next(m for m in operators.mutants(E2E_FILE, text) if m.op == "rel")
    folder = tempfile.mkdtemp(prefix="mutation-self-test-")
    try:
        original = compile_object(cc, source, text, folder, "original", ["-g"])
        moved = compile_object(cc, source, "\n\n" + text, folder, "moved", ["-g"])
        mutated = compile_object(cc, source, mutant.apply(text), folder, "mutated", ["-g"])
    finally:
        shutil.rmtree(folder)
    if original != moved:
        problems.append("tce: the digest depends on line numbers (debug information)")
    if original == mutated:
        problems.append(f"tce: {mutant.id} compiles to the unmutated object")


def main(args):
    problems = []
    total = check_mutants(args.source, problems)
    if args.pxflow:
        check_rows(args.pxflow, problems)
    if args.pxflow and args.dut_ref:
        check_dut_ref(args.pxflow, args.dut_ref, problems)
    if args.cc:
        check_end_to_end(args.cc, args.source, problems)
    for p in problems:
        print("FAIL " + p)
    print(f"{len(TARGETS)} files, {total} mutants, {len(operators.OPERATORS)} operators: "
          f"{'ok' if not problems else str(len(problems)) + ' problems'}")
    return 1 if problems else 0
