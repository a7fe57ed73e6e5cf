#!/usr/bin/env python3
"""`pxflow check --shard auto` under each CI engine's variables, merged into the unsharded run.

For each engine's variable set (GitLab parallel:, a Kubernetes Indexed Job, Slurm arrays whose
task ids start at 1, at 5, and in steps of 2) every shard runs `check --shard auto --json`; the
shard found must be the one the variables mean, the banner must name them, the file must record
K/M (never "auto"), and `pxflow merge` of the shards must equal the unsharded run's file in every
field but those that say how it ran (times, the shard list, the command). Then the refusals: no
variables, and malformed or inconsistent ones, each exit 2 with one line on stderr naming the
variables and nothing written. Usage: shard_auto.py PXFLOW. One line per case, then a summary.
"""
import json
import os
import subprocess
import sys
import tempfile

# A small fuzz campaign: 5 batches of 256 random pairs (the last 176), about 0.1 s a run.
CAMPAIGN = ["--backends", "ref-original,ref-local", "--cases", "1200", "--seed", "11"]
# Every variable --shard auto reads (hosts/cli/shard_auto.cpp): cleared from the test's own
# environment, which may be a CI job's.
VARIABLES = ["CI_NODE_INDEX", "CI_NODE_TOTAL", "JOB_COMPLETION_INDEX", "PXFLOW_SHARD_TOTAL",
             "SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_COUNT", "SLURM_ARRAY_TASK_MIN",
             "SLURM_ARRAY_TASK_STEP", "SLURM_ARRAY_TASK_MAX"]
# What says how a run went rather than what it found (hosts/harness/check/check_json.cpp): times, the
# command, and a single run's "shard" and "options" where a merge has "merged_from" and
# "missing_shards".
HOW_IT_RAN = {"seconds", "command", "shard", "options", "merged_from", "missing_shards"}


def slurm(ids, task, extra=None):
    """A Slurm array task's variables, as sbatch --array sets them for the ids `ids`."""
    env = {"SLURM_ARRAY_TASK_ID": str(task), "SLURM_ARRAY_TASK_COUNT": str(len(ids)),
           "SLURM_ARRAY_TASK_MIN": str(min(ids)), "SLURM_ARRAY_TASK_MAX": str(max(ids)),
           "SLURM_ARRAY_TASK_STEP": str(ids[1] - ids[0] if len(ids) > 1 else 1)}
    env.update(extra or {})
    return env


# Engine -> [(variables of one job, the shard K it is, M, the banner's source)].
ENGINES = {
    "gitlab": [({"CI_NODE_INDEX": str(k), "CI_NODE_TOTAL": "3"}, k, 3,
                "GitLab CI_NODE_INDEX=%d CI_NODE_TOTAL=3" % k) for k in (1, 2, 3)],
    "kubernetes": [({"JOB_COMPLETION_INDEX": str(i), "PXFLOW_SHARD_TOTAL": "3"}, i + 1, 3,
                    "Kubernetes JOB_COMPLETION_INDEX=%d PXFLOW_SHARD_TOTAL=3" % i)
                   for i in (0, 1, 2)],
    "slurm-from-1": [(slurm([1, 2, 3], t), t, 3,
                      "Slurm SLURM_ARRAY_TASK_ID=%d SLURM_ARRAY_TASK_COUNT=3 "
                      "SLURM_ARRAY_TASK_MIN=1" % t) for t in (1, 2, 3)],
    # Submitted from a GitLab job without parallel: (CI_NODE_TOTAL=1, which sbatch passes on).
    "slurm-from-5": [(slurm([5, 6, 7, 8], t, {"CI_NODE_TOTAL": "1"}), t - 4, 4,
                      "Slurm SLURM_ARRAY_TASK_ID=%d SLURM_ARRAY_TASK_COUNT=4 "
                      "SLURM_ARRAY_TASK_MIN=5" % t) for t in (5, 6, 7, 8)],
    "slurm-step-2": [(slurm([1, 3], t), (t + 1) // 2, 2,
                      "Slurm SLURM_ARRAY_TASK_ID=%d SLURM_ARRAY_TASK_COUNT=2 "
                      "SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_STEP=2" % t) for t in (1, 3)],
}

# Refusals: (name, variables, a string the one error line must hold).
REFUSALS = [
    ("none set", {}, "CI_NODE_INDEX/CI_NODE_TOTAL, Kubernetes JOB_COMPLETION_INDEX/"
     "PXFLOW_SHARD_TOTAL, Slurm SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT"),
    ("a GitLab job without parallel:", {"CI_NODE_TOTAL": "1"},
     "CI_NODE_TOTAL=1 without CI_NODE_INDEX is a GitLab job outside a matrix"),
    ("GitLab index only", {"CI_NODE_INDEX": "2"}, "CI_NODE_INDEX=2 is set but CI_NODE_TOTAL"),
    ("GitLab index above total", {"CI_NODE_INDEX": "4", "CI_NODE_TOTAL": "3"},
     "CI_NODE_INDEX must be 1 to 3"),
    ("GitLab index 0", {"CI_NODE_INDEX": "0", "CI_NODE_TOTAL": "3"}, "CI_NODE_INDEX must be 1"),
    ("GitLab total 0", {"CI_NODE_INDEX": "1", "CI_NODE_TOTAL": "0"}, "CI_NODE_TOTAL must be 1"),
    ("GitLab not a number", {"CI_NODE_INDEX": "two", "CI_NODE_TOTAL": "3"},
     "CI_NODE_INDEX='two': not a whole number"),
    ("GitLab negative", {"CI_NODE_INDEX": "-1", "CI_NODE_TOTAL": "3"},
     "CI_NODE_INDEX='-1': not a whole number"),
    ("Kubernetes without the total", {"JOB_COMPLETION_INDEX": "0"},
     "JOB_COMPLETION_INDEX=0 is set but PXFLOW_SHARD_TOTAL is not"),
    ("Kubernetes index = total", {"JOB_COMPLETION_INDEX": "3", "PXFLOW_SHARD_TOTAL": "3"},
     "JOB_COMPLETION_INDEX must be 0 to 2"),
    ("Kubernetes total not a number", {"JOB_COMPLETION_INDEX": "0", "PXFLOW_SHARD_TOTAL": "3x"},
     "PXFLOW_SHARD_TOTAL='3x': not a whole number"),
    ("Slurm without the count", {"SLURM_ARRAY_TASK_ID": "1"},
     "SLURM_ARRAY_TASK_ID=1 is set but SLURM_ARRAY_TASK_COUNT is not"),
    ("Slurm without the min", {"SLURM_ARRAY_TASK_ID": "5", "SLURM_ARRAY_TASK_COUNT": "4"},
     "SLURM_ARRAY_TASK_MIN is not set"),
    ("Slurm id below the min", slurm([5, 6, 7, 8], 4),
     "SLURM_ARRAY_TASK_ID is not one of 5, 6 .. 8"),
    ("Slurm id off the step", slurm([1, 3, 5], 2), "SLURM_ARRAY_TASK_ID is not one of 1, 3 .. 5"),
    ("Slurm list, not a range", dict(slurm([1, 2, 5], 5), SLURM_ARRAY_TASK_STEP="1"),
     "SLURM_ARRAY_TASK_MAX=5: the array's task ids are not one range with one step"),
    ("Slurm count 0", dict(slurm([1], 1), SLURM_ARRAY_TASK_COUNT="0"),
     "SLURM_ARRAY_TASK_COUNT must be 1"),
]


class Runner:
    def __init__(self, pxflow, tmp):
        self.pxflow, self.tmp, self.failed, self.cases = pxflow, tmp, 0, 0
        self.base = {k: v for k, v in os.environ.items() if k not in VARIABLES}

    def run(self, args, env=None):
        return subprocess.run([self.pxflow] + args, capture_output=True, text=True, timeout=120,
                              env=dict(self.base, **(env or {})))

    def case(self, name, problems):
        self.cases += 1
        if problems:
            self.failed += 1
            print("FAIL %s: %s" % (name, "; ".join(problems)))
        else:
            print("PASS %s" % name)

    def path(self, name):
        return os.path.join(self.tmp, name)


def differences(whole, merged, where=""):
    """The paths at which two check files differ in what they found."""
    if isinstance(whole, dict) and isinstance(merged, dict):
        out = []
        for key in sorted(set(whole) | set(merged)):
            if key in HOW_IT_RAN:
                continue
            if key not in whole or key not in merged:
                out.append("%s.%s only in %s" % (where, key, "whole" if key in whole else "merged"))
            else:
                out += differences(whole[key], merged[key], "%s.%s" % (where, key))
        return out
    if isinstance(whole, list) and isinstance(merged, list) and len(whole) == len(merged):
        return [d for i, (w, m) in enumerate(zip(whole, merged))
                for d in differences(w, m, "%s[%d]" % (where, i))]
    return [] if whole == merged else ["%s: %r (whole) != %r (merged)" % (where, whole, merged)]


def engine_case(r, engine, jobs, whole):
    problems, files = [], []
    for env, k, m, source in jobs:
        out = r.path("%s-%d.json" % (engine, k))
        run = r.run(["check"] + CAMPAIGN + ["--shard", "auto", "--json", out], env)
        if run.returncode != 0:
            problems.append("shard %d/%d exit %d: %s" % (k, m, run.returncode, run.stderr.strip()))
            continue
        banner = ", shard %d/%d (--shard auto: %s)" % (k, m, source)
        if banner not in run.stdout:
            problems.append("no '%s' in the output: %s" % (banner, run.stdout.splitlines()[:1]))
        got = json.load(open(out))
        if (got["shard"]["index"], got["shard"]["count"]) != (k, m):
            problems.append("%s holds shard %s, not %d/%d" % (out, got["shard"], k, m))
        if "--shard %d/%d " % (k, m) not in got["command"] or "--shard auto" in got["command"]:
            problems.append("%s: command %r does not say --shard %d/%d" % (out, got["command"], k, m))
        files.append(out)
    merged_path = r.path("%s-merged.json" % engine)
    merge = r.run(["merge", "--json", merged_path] + files[::-1])
    if merge.returncode != 0:
        problems.append("merge exit %d: %s" % (merge.returncode, merge.stderr.strip()))
    else:
        problems += differences(whole, json.load(open(merged_path)))[:5]
    r.case("%s: %d shards merged equal the unsharded run" % (engine, len(jobs)), problems)


def refusal_case(r, name, env, expected):
    out = r.path("refused.json")
    run = r.run(["check"] + CAMPAIGN + ["--shard", "auto", "--json", out], env)
    lines = run.stderr.splitlines()
    problems = []
    if run.returncode != 2:
        problems.append("exit %d, not 2" % run.returncode)
    if len(lines) != 1 or not lines[0].startswith("pxflow: error: --shard auto: "):
        problems.append("stderr is not one error line: %r" % run.stderr)
    elif expected not in lines[0]:
        problems.append("the line lacks %r: %s" % (expected, lines[0]))
    if run.stdout or os.path.exists(out):
        problems.append("output left: stdout %r, %s %s" % (run.stdout, out, os.path.exists(out)))
    r.case("refused, %s" % name, problems)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: shard_auto.py PXFLOW")
    with tempfile.TemporaryDirectory(prefix="pxflow-shard-auto-") as tmp:
        r = Runner(sys.argv[1], tmp)
        whole_run = r.run(["check"] + CAMPAIGN + ["--json", r.path("whole.json")])
        if whole_run.returncode != 0:
            print("FAIL the unsharded run: exit %d: %s" % (whole_run.returncode, whole_run.stderr))
            return 1
        whole = json.load(open(r.path("whole.json")))
        for engine, jobs in ENGINES.items():
            engine_case(r, engine, jobs, whole)
        for name, env, expected in REFUSALS:
            refusal_case(r, name, env, expected)
        print("%d of %d failed" % (r.failed, r.cases))
        return 1 if r.failed else 0


if __name__ == "__main__":
    sys.exit(main())
