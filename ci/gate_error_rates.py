#!/usr/bin/env python3
"""The error rates of pxflow's performance gate (docs/harness.md, "The gate's error rates").

Runs `pxflow compare --run A B` many times on this machine:
  A/A        the same binary on both sides: every "fail" is a false alarm;
  A/B +P %   B plants a P % slowdown (PXFLOW_BENCH_PLANTED_SLOWDOWN: P % more batches run than
             counted, known work per frame): every "fail" is a detection (the power).
Each trial's two bench files are judged again at every --gate threshold (pxflow compare FILES
--fail-above PCT), so one run of the processes gives every threshold's verdict. --hog N runs N
busy-looping processes for the whole experiment (a disturbed machine).
The point is batch 1 at 320x240 on one thread with --min-time 0.2 per process: fast enough that
every sample of both sides is the mean of many runs (the knob rounds B's runs per sample up to a
multiple of 20 at 5 %, of 10 at 10 %), so the two sides differ in the planted work alone. (At
64x64, where a frame is one 4 KiB page, this machine's processes fall into two clusters 1.5x
apart, with or without ASLR or CPU pinning: docs/harness.md, "The gate's error rates".)

Usage: ci/gate_error_rates.py build/pxflow [--backends ref-local,cpu] [--trials 20]
       [--rounds 10] [--gates 0,2,5] [--planted 5,10] [--hog 1] [--extra "--threads 1"]
       [--json out.json]     (under `taskset -c N`, every process runs on CPU N)
Prints one Markdown table; exit 0 (the figures are the result, not a verdict).
"""
import argparse
import json
import multiprocessing
import os
import stat
import subprocess
import sys
import tempfile
import time

OUTCOME = {0: "pass", 1: "fail", 3: "inconclusive"}


def hog():
    while True:
        pass


def planted_wrapper(folder, pxflow, percent):
    """A program that is `pxflow` with a planted slowdown of `percent` %."""
    path = os.path.join(folder, f"pxflow-planted-{percent}")
    with open(path, "w") as f:
        f.write(f"#!/bin/sh\nPXFLOW_BENCH_PLANTED_SLOWDOWN={percent} exec '{pxflow}' \"$@\"\n")
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)
    return path


def trial(pxflow, a, b, backend, args, folder):
    """One compare --run: the outcome at every gate, from its two bench files."""
    out = os.path.join(folder, "cmp")
    bench = (f"--backends {backend} --batch {args.batch} --sizes {args.size} "
             f"--min-time {args.min_time} --no-bound {args.extra}").strip()
    run = subprocess.run([pxflow, "compare", "--run", a, b, "--rounds", str(args.rounds),
                          "--bench-args", bench, "--fail-above", str(args.gates[0]), "--out", out],
                         capture_output=True, text=True)
    if run.returncode not in OUTCOME:
        sys.exit(f"gate_error_rates: compare --run exited {run.returncode}: {run.stderr.strip()}")
    outcomes = {}
    for gate in args.gates:
        judged = subprocess.run([pxflow, "compare", os.path.join(out, "bench-A.json"),
                                 os.path.join(out, "bench-B.json"), "--fail-above", str(gate)],
                                capture_output=True, text=True)
        outcomes[gate] = OUTCOME.get(judged.returncode, f"exit {judged.returncode}")
    with open(os.path.join(out, "compare.json")) as f:
        rows = json.load(f)["rows"]
    ratio = rows[0]["ratio"] if rows else None
    subprocess.run(["rm", "-rf", out], check=True)
    return outcomes, ratio


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("pxflow")
    p.add_argument("--backends", default="ref-local,cpu")
    p.add_argument("--trials", type=int, default=20)
    p.add_argument("--rounds", type=int, default=10)
    p.add_argument("--gates", default="0,2,5")
    p.add_argument("--planted", default="5,10")
    p.add_argument("--batch", default="1")
    p.add_argument("--size", default="320x240")
    p.add_argument("--min-time", default="0.2")
    p.add_argument("--hog", type=int, default=0)
    p.add_argument("--extra", default="--threads 1", help="more bench options, e.g. \"--threads 1\"")
    p.add_argument("--json")
    args = p.parse_args()
    args.gates = [float(g) for g in args.gates.split(",")]
    pxflow = os.path.abspath(args.pxflow)
    hogs = [multiprocessing.Process(target=hog, daemon=True) for _ in range(args.hog)]
    for h in hogs:
        h.start()
    results = []
    started = time.time()
    try:
        with tempfile.TemporaryDirectory() as folder:
            sides = [("A/A", pxflow)] + [(f"A/B +{q} %", planted_wrapper(folder, pxflow, int(q)))
                                         for q in args.planted.split(",")]
            for backend in args.backends.split(","):
                for name, b in sides:
                    counts = {g: {"fail": 0, "pass": 0, "inconclusive": 0} for g in args.gates}
                    ratios = []
                    for _ in range(args.trials):
                        outcomes, ratio = trial(pxflow, pxflow, b, backend, args, folder)
                        for g, o in outcomes.items():
                            counts[g][o] = counts[g].get(o, 0) + 1
                        if ratio is not None:
                            ratios.append(ratio)
                    ratios.sort()
                    for g in args.gates:
                        results.append({"backend": backend, "experiment": name, "gate": g,
                                        "trials": args.trials, **counts[g],
                                        "median_ratio": ratios[len(ratios) // 2] if ratios else None})
                    print(f"# {backend} {name}: done ({time.time() - started:.0f} s)", file=sys.stderr)
    finally:
        for h in hogs:
            h.terminate()
    condition = f"{args.hog} CPU hog(s)" if args.hog else "quiet"
    print(f"machine: {condition}; each trial: compare --run with {args.rounds} rounds "
          f"(--bench-args \"--batch {args.batch} --sizes {args.size} --min-time {args.min_time} "
          f"--no-bound {args.extra}\"); affinity: CPUs {sorted(os.sched_getaffinity(0))}\n")
    print("| backend | experiment | --fail-above | trials | fail | pass | inconclusive | median ratio |")
    print("|---|---|---|---|---|---|---|---|")
    for r in results:
        ratio = f"{r['median_ratio']:.3f}" if r["median_ratio"] else "-"
        print(f"| {r['backend']} | {r['experiment']} | {r['gate']:g} % | {r['trials']} | "
              f"{r['fail']} | {r['pass']} | {r['inconclusive']} | {ratio} |")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"condition": condition, "rounds": args.rounds, "results": results}, f,
                      indent=1)


if __name__ == "__main__":
    main()
