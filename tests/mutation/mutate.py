#!/usr/bin/env python3
"""Mutation testing of the in-tree kernels against `pxflow check` (docs/mutation.md).

  mutate.py list --seed 2026 --per-family 40           the mutants a campaign would run
  mutate.py run --seed 2026 --per-family 40 --out DIR  apply, rebuild, check, report
  mutate.py run --only results/results.json --out DIR  rerun a campaign's survivors (or ids)
  mutate.py report --out DIR                           rescore DIR against equivalent.txt
  mutate.py self-test --pxflow build/pxflow            every operator on every file, in memory

`run` edits the kernel files of the source tree in place, one mutant at a time, and always puts
them back (also on Ctrl-C or SIGTERM); rebuilds only the targets that compile the file; a mutant
whose compiled code is byte-identical to the unmutated build's is equivalent without a run; else
`pxflow check --backends ref-original,ROWS --require ROWS` (those this machine runs) on the
default corpus, stopped at its
first FAIL line: killed (a FAIL line, a non-zero exit, a crash or a hang), survived (exit 0), or
build-failed. A survivor listed in equivalent.txt (reviewed by a human) counts as equivalent.
Any other survivor is rerun through the test of .ci/run that runs its family's code under a
memory checker (targets.Family.memory_test), by ctest as ci/run-tests.sh runs it: for host code
the ASan+UBSan stage's test, rebuilt in --sanitizer-build (configured like that stage): killed
(sanitizer); for the OpenCL C kernels the Release stage's Oclgrind test: killed (Oclgrind). So a
kill names a test CI runs. A survivor still standing and listed in undetectable.txt (reviewed: no
check can see it on this machine) counts as undetectable, never as killed.
"""

import argparse
import json
import os
import random
import signal
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import operators  # noqa: E402
import report  # noqa: E402
import tce  # noqa: E402
from targets import FAMILIES, OPTION_ROWS, TARGETS  # noqa: E402

SOURCE = os.path.dirname(os.path.dirname(HERE))
EQUIVALENTS = os.path.join(HERE, "equivalent.txt")
UNDETECTABLE = os.path.join(HERE, "undetectable.txt")
# ci/run-tests.sh's sanitizer stage: the options its tests run with.
SANITIZER_ENV = {"ASAN_OPTIONS": "detect_leaks=1:abort_on_error=1",
                 "UBSAN_OPTIONS": "print_stacktrace=1:halt_on_error=1"}


class Stop(Exception):
    """SIGTERM, turned into an exception so that the finally blocks restore the files."""


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def write(path, text):
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def load_equivalents(path=EQUIVALENTS):
    """{mutant id: reason} from equivalent.txt (or undetectable.txt): `ID  reason`, # comments."""
    found = {}
    for n, line in enumerate(read(path).splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        ident, _, reason = line.partition(" ")
        if not reason.strip():
            raise SystemExit(f"mutate.py: error: {path}:{n}: '{ident}' has no reason")
        found[ident] = reason.strip()
    return found


def all_mutants(source, families=None):
    """{target path: (text, [Mutant])} for the table's files (of the given families)."""
    result = {}
    for t in TARGETS:
        if families and t.family not in families:
            continue
        text = read(os.path.join(source, t.path))
        result[t.path] = (text, operators.mutants(t.path, text))
    return result


def select(source, seed, per_family, families, ops=operators.DEFAULT_OPERATORS):
    """per_family mutants of each family, seeded: operators taken in turn, so that the rare
    ones (min/max, ==) are drawn as well as the many constants. Only the operators `ops`."""
    chosen = []
    by_path = all_mutants(source, families)
    for family in families:
        pool = {}
        for t in TARGETS:
            if t.family == family:
                for m in by_path[t.path][1]:
                    if m.op in ops:
                        pool.setdefault(m.op, []).append(m)
        rng = random.Random(f"{seed}:{family}")
        queues = []
        for op in sorted(pool):
            items = list(pool[op])
            rng.shuffle(items)
            queues.append(items)
        rng.shuffle(queues)
        picked = []
        while len(picked) < per_family and any(queues):
            for q in queues:
                if q and len(picked) < per_family:
                    picked.append(q.pop())
        chosen.extend(picked)
    chosen.sort(key=lambda m: (m.path, m.start, m.op))
    return chosen, by_path


def chosen_only(source, spec):
    """The mutants --only names: a campaign's results.json (its survivors, whose diffs must be
    today's: a moved line fails), a file of ids (one a line, # comments), or comma-separated ids."""
    by_path = all_mutants(source)
    index = {m.id: m for _, ms in by_path.values() for m in ms}
    wanted = {}
    if spec.endswith(".json"):
        with open(spec, encoding="utf-8") as f:
            wanted = {r["id"]: r["diff"] for r in json.load(f)["mutants"] if r["status"] == "survived"}
    elif os.path.isfile(spec):
        for line in read(spec).splitlines():
            if line.split("#")[0].strip():
                wanted[line.split()[0]] = None
    else:
        wanted = dict.fromkeys(x for x in spec.split(",") if x)
    chosen = []
    for ident, diff in wanted.items():
        m = index.get(ident)
        if m is None:
            raise SystemExit(f"mutate.py: error: {ident} is not a mutant of the tree (did its line move?)")
        if diff is not None and m.diff(by_path[m.path][0]) != diff:
            raise SystemExit(f"mutate.py: error: {ident} now makes another change than in {spec}")
        chosen.append(m)
    chosen.sort(key=lambda m: (m.path, m.start, m.op))
    return chosen, by_path


def target_of(path):
    return next(t for t in TARGETS if t.path == path)


def ninja(build, targets, log):
    r = subprocess.run(["ninja", "-C", build, *targets], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        log.write(r.stdout)
    return r.returncode == 0, r.stdout


def family_targets(family):
    """Every build target of a family: what compiles its kernel, then what links it."""
    f = FAMILIES[family]
    return list(dict.fromkeys(f.compile_targets + f.link_targets))


_RUNNABLE = {}


def runnable(build):
    """The rows `pxflow backends` of this build says this machine can run (an ISA row the CPU
    lacks, avx512bw on an AVX2 machine, is checked where it can run and skipped here)."""
    if build not in _RUNNABLE:
        out = subprocess.run([os.path.join(build, "pxflow"), "backends", "--json", "-"],
                             stdout=subprocess.PIPE, text=True, check=True).stdout
        _RUNNABLE[build] = {b["backend"] for b in json.loads(out)["backends"] if b["available"]}
    return _RUNNABLE[build] | OPTION_ROWS


def check_command(build, target):
    family = FAMILIES[target.family]
    rows = ",".join(target.rows)
    required = ",".join(r for r in target.rows if r in runnable(build))
    extra = [a.format(build=os.path.abspath(build)) for a in family.check_args]
    # --no-repro: the verdict is the first FAIL line; a reproducer would only litter the working
    # folder (the source tree) with pxflow-repro-N folders.
    return [os.path.join(build, "pxflow"), "check", *extra, "--backends", "ref-original," + rows,
            "--require", required, "--no-repro"]


def run_check(cmd, timeout, env=None):
    """(outcome, detail, seconds): stops at the first FAIL line."""
    start = time.monotonic()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            errors="replace", start_new_session=True,
                            env=dict(os.environ, **env) if env else None)
    timed_out = threading.Event()

    def kill():
        timed_out.set()
        os.killpg(proc.pid, signal.SIGKILL)

    timer = threading.Timer(timeout, kill)
    timer.start()
    first_fail, tail = None, []
    try:
        for line in proc.stdout:
            tail = (tail + [line.rstrip()])[-5:]
            if line.startswith("FAIL "):
                first_fail = line.rstrip()
                try:
                    os.killpg(proc.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                break
        proc.wait()
    finally:
        timer.cancel()
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    seconds = time.monotonic() - start
    if first_fail:
        return "killed", first_fail, seconds
    if timed_out.is_set():
        return "killed", f"no verdict after {timeout:.0f} s (hang)", seconds
    if proc.returncode == 0:
        return "survived", "", seconds
    if proc.returncode < 0:
        return "killed", f"check died of signal {-proc.returncode}", seconds
    return "killed", f"exit {proc.returncode}: " + " | ".join(tail), seconds


def baseline(args, targets, log):
    """Build the unmutated tree, record its artifacts, check every row group once."""
    families = sorted({t.family for t in targets})
    builds = sorted({x for f in families for x in family_targets(f)})
    ok, out = ninja(args.build, builds, log)
    if not ok:
        raise SystemExit("mutate.py: error: the unmutated tree does not build (see the log)")
    artifacts = {f: tce.snapshot(args.build, FAMILIES[f].artifacts) for f in families}
    for f in families:
        if FAMILIES[f].artifacts and not artifacts[f]:
            raise SystemExit(f"mutate.py: error: no build output of family {f} in {args.build}")
    checks = {}
    for t in targets:
        key = t.rows
        if key in checks:
            continue
        outcome, detail, seconds = run_check(check_command(args.build, t), args.max_timeout)
        checks[key] = {"ok": outcome == "survived", "detail": detail, "seconds": seconds}
        print(f"baseline {','.join(key)}: {'passed' if outcome == 'survived' else detail} "
              f"({seconds:.1f} s)", flush=True)
    return artifacts, checks


def run_mutant(args, m, text, artifacts, checks, log):
    t = target_of(m.path)
    family = FAMILIES[t.family]
    base = checks[t.rows]
    result = {"id": m.id, "path": m.path, "op": m.op, "family": t.family, "rows": list(t.rows),
              "diff": m.diff(text)}
    if not base["ok"]:
        return dict(result, status="not-run", detail="the unmutated check fails: " + base["detail"])
    path = os.path.join(args.source, m.path)
    start = time.monotonic()
    try:
        write(path, m.apply(text))
        ok, _ = ninja(args.build, list(family.compile_targets), log)
        if ok and family.artifacts and tce.snapshot(args.build, family.artifacts) == artifacts[t.family]:
            return dict(result, status="equivalent", detail="identical compiled code")
        if ok:
            ok, _ = ninja(args.build, list(family.link_targets), log)
        if not ok:
            return dict(result, status="build-failed", detail="does not compile")
        build_s = time.monotonic() - start
        # A mutant may slow a row down a lot without hanging (lavapipe ran a flow.comp mutant
        # with an out-of-bounds private array 6x slower, 18.7 s, and passed): the tool's own
        # limit is generous; the check's verdicts come first (a worker's hang verdict comes after
        # 2 x --device-timeout = 60 s at the defaults, IsolatedRow::allowance).
        timeout = min(args.max_timeout, max(75.0, 10 * base["seconds"]))
        outcome, detail, seconds = run_check(check_command(args.build, t), timeout)
        if t.family == "opencl" and "required but cannot run" in detail:
            outcome, detail = "build-failed", detail  # PoCL compiles the kernel at run time
        return dict(result, status=outcome, detail=detail, build_s=round(build_s, 1),
                    check_s=round(seconds, 1))
    finally:
        write(path, text)


def run_ctest(build, test, timeout, env=None):
    """(outcome, detail, seconds) of one ctest test of `build`: its first error line names it."""
    cmd = ["ctest", "--test-dir", build, "-R", f"^{test}$", "--output-on-failure",
           "--timeout", str(int(timeout))]
    start = time.monotonic()
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       errors="replace", env=dict(os.environ, **env) if env else None)
    seconds = time.monotonic() - start
    if "No tests were found" in r.stdout:
        raise SystemExit(f"mutate.py: error: {build} has no test {test} (configure it as CI does)")
    if r.returncode == 0:
        return "survived", "", seconds
    marks = ("FAIL ", "ERROR: AddressSanitizer", "runtime error:", "***Timeout", "Exception:")
    first = next((ln.strip() for ln in r.stdout.splitlines() if any(k in ln for k in marks)),
                 r.stdout.strip().splitlines()[-1] if r.stdout.strip() else f"exit {r.returncode}")
    return "killed", f"{test}: {first}", seconds


class CiMemoryTest:
    """The memory checkers' pass over survivors of the default check: the family's test of .ci/run
    that runs its code under a memory checker (targets.Family.memory_test), run by ctest exactly
    as ci/run-tests.sh runs it: from --sanitizer-build with the sanitizer stage's options
    (killed-sanitizer), or from --build (killed-oclgrind: Oclgrind's test is a Release-stage test).
    Its unmutated run comes first, once per test, from the restored tree."""

    def __init__(self, args, log):
        self.args, self.log, self.base, self.built = args, log, {}, set()

    def _build(self, stage):
        return self.args.sanitizer_build if stage == "sanitizer" else self.args.build

    def applies(self, t):
        test = FAMILIES[t.family].memory_test
        return bool(test) and bool(self._build(test[0]))

    def _run(self, t):
        stage, test = FAMILIES[t.family].memory_test
        build = self._build(stage)
        ok, _ = ninja(build, family_targets(t.family), self.log)
        if stage == "sanitizer":
            self.built.add(t.family)
        if not ok:
            return "build-failed", f"the {stage} build fails", 0.0
        base = self.base.get(test, {}).get("seconds", 60.0)
        return run_ctest(build, test, max(300.0, 5 * base), SANITIZER_ENV if stage == "sanitizer" else None)

    def run(self, m, text):
        """(status, detail): killed-sanitizer, killed-oclgrind or survived."""
        t = target_of(m.path)
        stage, test = FAMILIES[t.family].memory_test
        if test not in self.base:
            outcome, detail, seconds = self._run(t)
            self.base[test] = {"ok": outcome == "survived", "detail": detail, "seconds": seconds}
            print(f"{stage} baseline {test}: {'passed' if outcome == 'survived' else detail} "
                  f"({seconds:.1f} s)", flush=True)
        if not self.base[test]["ok"]:
            return "survived", f"the unmutated {test} fails: " + self.base[test]["detail"]
        path = os.path.join(self.args.source, m.path)
        try:
            write(path, m.apply(text))
            outcome, detail, _ = self._run(t)
        finally:
            write(path, text)
        if outcome == "build-failed":
            return "survived", detail
        status = "killed-sanitizer" if stage == "sanitizer" else "killed-oclgrind"
        return (status, detail) if outcome == "killed" else ("survived", "")

    def restore(self):
        """The sanitizer build relinked from the restored tree (command_run relinks --build)."""
        targets = sorted({x for f in self.built for x in family_targets(f)})
        if targets and self.args.sanitizer_build:
            ninja(self.args.sanitizer_build, targets, self.log)


def classify(args, m, r, text, equivalents, undetectable, memory):
    """A survivor of the default check: reviewed equivalent, killed by .ci/run's memory-checker
    test of its family (ASan+UBSan for host code, Oclgrind for OpenCL C), reviewed undetectable
    here, or survived."""
    if r["status"] != "survived":
        return r
    if m.id in equivalents:
        return dict(r, status="equivalent", detail="reviewed: " + equivalents[m.id])
    if memory.applies(target_of(m.path)):
        status, detail = memory.run(m, text)
        if status != "survived":
            return dict(r, status=status, detail=detail)
    elif not FAMILIES[target_of(m.path).family].memory_test:
        r = dict(r, detail="device code: no memory checker runs it here")
    if m.id in undetectable:
        return dict(r, status="undetectable", detail="reviewed: " + undetectable[m.id])
    return r


def command_run(args):
    families = args.families.split(",") if args.families else sorted(FAMILIES)
    if args.only:
        chosen, by_path = chosen_only(args.source, args.only)
        families = sorted({target_of(m.path).family for m in chosen})
    else:
        chosen, by_path = select(args.source, args.seed, args.per_family, families,
                                 chosen_operators(args))
    equivalents, undetectable = load_equivalents(), load_equivalents(UNDETECTABLE)
    if args.sanitizer_build == "auto":
        auto = os.path.join(args.source, "build-sanitize")
        args.sanitizer_build = auto if os.path.isfile(os.path.join(auto, "build.ninja")) else ""
    os.makedirs(args.out, exist_ok=True)
    log = open(os.path.join(args.out, "build.log"), "w")
    originals = {p: by_path[p][0] for p in {m.path for m in chosen}}

    def on_term(signum, frame):
        raise Stop()

    signal.signal(signal.SIGTERM, on_term)
    results, started = [], time.time()
    meta = {"seed": args.seed, "per_family": args.per_family, "families": families,
            "operators": list(chosen_operators(args)) if not args.only else None,
            "command": " ".join(["tests/mutation/mutate.py"] + sys.argv[1:]),
            "only": args.only, "sanitizer_build": args.sanitizer_build}
    memory = CiMemoryTest(args, log)
    try:
        artifacts, checks = baseline(args, [target_of(p) for p in sorted({m.path for m in chosen})], log)
        meta["baseline"] = {",".join(k): v for k, v in checks.items()}
        for n, m in enumerate(chosen, 1):
            text = by_path[m.path][0]
            r = run_mutant(args, m, text, artifacts, checks, log)
            r = classify(args, m, r, text, equivalents, undetectable, memory)
            results.append(r)
            print(f"[{n}/{len(chosen)}] {r['status']:12} {m.id}  {r.get('detail', '')[:110]}",
                  flush=True)
            report.write(args.out, meta, results, time.time() - started)
    except (KeyboardInterrupt, Stop):
        print("mutate.py: interrupted; the files are restored", file=sys.stderr)
        return 130
    finally:
        for p, text in originals.items():
            full = os.path.join(args.source, p)
            if read(full) != text:
                write(full, text)
        report.write(args.out, meta, results, time.time() - started)
        if not args.no_restore_build:
            ninja(args.build, sorted({x for f in families for x in FAMILIES[f].link_targets}), log)
            memory.restore()
    return 0


def command_report(args):
    """Results rescored against today's equivalent.txt (a review after the campaign)."""
    with open(os.path.join(args.out, "results.json"), encoding="utf-8") as f:
        doc = json.load(f)
    equivalents, undetectable = load_equivalents(), load_equivalents(UNDETECTABLE)
    for r in doc["mutants"]:
        reviewed = r["status"] in ("equivalent", "undetectable") and r["detail"].startswith("reviewed: ")
        if reviewed or r["status"] == "survived":
            if r["id"] in equivalents:
                r["status"], r["detail"] = "equivalent", "reviewed: " + equivalents[r["id"]]
            elif r["id"] in undetectable:
                r["status"], r["detail"] = "undetectable", "reviewed: " + undetectable[r["id"]]
            else:
                r["status"], r["detail"] = "survived", ""
    keys = ("seed", "per_family", "families", "operators", "command", "baseline", "only",
            "sanitizer_build")
    meta = {k: doc[k] for k in keys if k in doc}
    report.write(args.out, meta, doc["mutants"], doc["seconds"])
    print(open(os.path.join(args.out, "results.md"), encoding="utf-8").read().split("\n## ")[0])
    return 0


def chosen_operators(args):
    """--operators: default (the reported campaigns'), memory, all, or a comma-separated list."""
    named = {"default": operators.DEFAULT_OPERATORS, "memory": operators.MEMORY_OPERATORS,
             "all": operators.OPERATORS}
    ops = named.get(args.operators) or tuple(args.operators.split(","))
    unknown = [op for op in ops if op not in operators.OPERATORS]
    if unknown:
        raise SystemExit(f"mutate.py: error: --operators: unknown {', '.join(unknown)} (known: "
                         f"default, memory, all, {', '.join(operators.OPERATORS)})")
    return ops


def command_list(args):
    families = args.families.split(",") if args.families else sorted(FAMILIES)
    chosen, by_path = select(args.source, args.seed, args.per_family, families,
                             chosen_operators(args))
    for m in chosen:
        print(m.id)
        print(m.diff(by_path[m.path][0]))
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    for name in ("run", "list"):
        p = sub.add_parser(name)
        p.add_argument("--seed", type=int, default=2026)
        p.add_argument("--per-family", type=int, default=40)
        p.add_argument("--families", default="", help="comma-separated (default: all): "
                       + ",".join(sorted(FAMILIES)))
        p.add_argument("--operators", default="default",
                       help="default (those of the reported campaigns), memory (a length, a bound "
                       "or a size's term one off: out-of-bounds accesses), all, or a list")
        p.add_argument("--source", default=SOURCE)
        p.add_argument("--build", default=os.path.join(SOURCE, "build"))
    run = sub.choices["run"]
    run.add_argument("--out", required=True, help="folder for results.json, results.md, build.log")
    run.add_argument("--max-timeout", type=float, default=120.0,
                     help="seconds a check may run at most (a hang is a kill)")
    run.add_argument("--only", default="",
                     help="run these mutants instead of a seeded choice: a results.json (its "
                     "survivors), a file of ids, or comma-separated ids")
    run.add_argument("--sanitizer-build", default="auto",
                     help="the ASan+UBSan build folder survivors of host code are rechecked in "
                     "(default: build-sanitize when configured; '' for none)")
    run.add_argument("--no-restore-build", action="store_true",
                     help="leave the build as the last mutant left it (faster)")
    rep = sub.add_parser("report", help="rescore a campaign's results against equivalent.txt")
    rep.add_argument("--out", required=True, help="the campaign's folder (results.json)")
    st = sub.add_parser("self-test")
    st.add_argument("--pxflow", help="the binary whose rows the table must name")
    st.add_argument("--dut-ref", help="the pxflow-dut-ref the table's dut family must run")
    st.add_argument("--cc", help="a C compiler: compile one mutant in a temporary folder")
    st.add_argument("--source", default=SOURCE)
    args = parser.parse_args()
    if args.command == "self-test":
        import self_test
        return self_test.main(args)
    if args.command == "report":
        return command_report(args)
    if args.command == "list":
        return command_list(args)
    return command_run(args)


if __name__ == "__main__":
    sys.exit(main())
