#!/usr/bin/env python3
"""Makes a real report and validates its results.json against docs/report-schema.json, then
checks that the schema refuses copies with a field removed, of the wrong type or not listed, so
that the validation is shown to be able to fail, and that results.csv and conformance.csv have a
column per field the schema lists for a bench row and a check backend. Usage: check_report_schema.py PXFLOW SCHEMA OUTDIR.
Exit 0: all as expected; 1: a failure (listed); 77: python3-jsonschema is not installed."""
import copy
import json
import os
import shutil
import subprocess
import sys

try:
    import jsonschema
except ImportError:
    print("SKIP: python3-jsonschema not installed (ci/packages.txt lists it)")
    sys.exit(77)


def run(args):
    r = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        print("FAIL: %s exited %d\n%s%s" % (" ".join(args), r.returncode, r.stdout, r.stderr))
        sys.exit(1)


def first_chart_style(results):
    for section in results["sections"]:
        for chart in section["charts"]:
            items = chart["series"] or chart["bars"]
            if items:
                return items[0]["style"]
    raise KeyError("no chart with a series or a bar")


# (what the copy breaks, how): each copy must be refused.
MUTATIONS = [
    ("provenance.build.commit removed", lambda j: j["provenance"]["build"].pop("commit")),
    ("provenance.build.dirty a string",
     lambda j: j["provenance"]["build"].__setitem__("dirty", "no")),
    ("provenance.machine.cores a string",
     lambda j: j["provenance"]["machine"].__setitem__("cores", "2")),
    ("commands.report null", lambda j: j["commands"].__setitem__("report", None)),
    ("check.backends[0].state unknown",
     lambda j: j["check"]["backends"][0].__setitem__("state", "great")),
    ("bench.rows[0].frames_per_s a string",
     lambda j: j["bench"]["rows"][0].__setitem__("frames_per_s", "fast")),
    ("bench.rows[0].exact_clock removed", lambda j: j["bench"]["rows"][0].pop("exact_clock")),
    ("bench.backends removed", lambda j: j["bench"].pop("backends")),
    ("accuracy removed", lambda j: j.pop("accuracy")),
    ("accuracy.rows[0].mean_error_px a string",
     lambda j: j["accuracy"]["rows"][0].__setitem__("mean_error_px", "0.1")),
    ("sections[0].rows[0][0] a number", lambda j: j["sections"][0]["rows"][0].__setitem__(0, 5)),
    ("a chart style's colour not #rrggbb",
     lambda j: first_chart_style(j).__setitem__("colour", "blue")),
    ("gap8.variants entry without cycles",
     lambda j: next(iter(next(iter(j["gap8"]["variants"].values())).values())).pop("cycles")),
    ("schema_version 2", lambda j: j.__setitem__("schema_version", 2)),
    ("pxflow.commit removed", lambda j: j["pxflow"].pop("commit")),
    ("check.backends[0].backend removed", lambda j: j["check"]["backends"][0].pop("backend")),
    ("bench.rows[0] with a key the schema does not list",
     lambda j: j["bench"]["rows"][0].__setitem__("furlongs_per_frame", 1.0)),
    ("check.backends[0] with a key the schema does not list",
     lambda j: j["check"]["backends"][0].__setitem__("colour", "green")),
    ("comparison.rows[0] with a key the schema does not list",
     lambda j: j["comparison"]["rows"][0].__setitem__("furlongs", 1.0)),
    ("comparison.rows[0].verdict unknown",
     lambda j: j["comparison"]["rows"][0].__setitem__("verdict", "better")),
    ("bench.provenance.machine.host removed",
     lambda j: j["bench"]["provenance"]["machine"].pop("host")),
    ("provenance.bench_files[1].machine.host removed",
     lambda j: j["provenance"]["bench_files"][1]["machine"].pop("host")),
    ("provenance.bench_files[0].complete a string",
     lambda j: j["provenance"]["bench_files"][0].__setitem__("complete", "yes")),
    ("bench.rows[0].bound_unit unknown",
     lambda j: j["bench"]["rows"][0].__setitem__("bound_unit", "furlongs")),
    ("gap8 cycles a fraction",
     lambda j: next(iter(next(iter(j["gap8"]["variants"].values())).values())).__setitem__(
         "cycles", 0.5)),
]


def csv_header_failures(schema, report):
    """results.csv and conformance.csv have a column per field of the schema's bench row and
    check backend (the check's failure lines and limit lists and a bench row's samples aside:
    lists, results.json only)."""
    definitions = schema["definitions"]
    backend = definitions["check"]["properties"]["backends"]["items"]
    expected = {"results.csv": set(definitions["bench_row"]["properties"]) - {
        "samples_ns_per_frame", "samples_per_process", "process_medians_ns_per_frame", "params"},
                "conformance.csv": set(backend["properties"]) - {"failures", "limits"}}
    failures = []
    for name, want in expected.items():
        with open(os.path.join(report, name)) as f:
            header = f.readline().strip().split(",")
        if set(header) != want:
            failures.append("%s: columns %s, the schema's fields %s" % (name, sorted(header),
                                                                        sorted(want)))
    return failures


def bound_failures(results):
    """Every timed bench row shows its bound and the fraction achieved, or says why it has none
    (docs/harness.md, "The bound of every row"), and the report has the bound section."""
    failures = []
    for row in results["bench"]["rows"]:
        if not row["samples_ns_per_frame"]:
            continue
        bound = row.get("bound", "")
        if not bound:
            failures.append("timed bench row of %s without its bound" % row["backend"])
        elif not bound.startswith("none: ") and not row.get("bound_fraction"):
            failures.append("bench row of %s: a bound but no fraction" % row["backend"])
    if not any(s["key"] == "bound" for s in results["sections"]):
        failures.append("no section 'bound' (every row's fraction of its bound)")
    return failures


def main():
    pxflow, schema_path, out = sys.argv[1:4]
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    c, b, r = (os.path.join(out, n) for n in ("c.json", "b.json", "report"))
    run([pxflow, "check", "--backends", "ref-original,ref-local", "--generated-only", "--json", c])
    run([pxflow, "bench", "--backends", "ref-original,ref-local", "--batch", "1", "--min-time",
         "0", "--json", b])
    # --quick: a short accuracy run, so that its rows are in the file and validated too; a copy
    # of the bench file as a second one, so that the comparison is too.
    b2 = os.path.join(out, "b2.json")
    shutil.copyfile(b, b2)
    run([pxflow, "report", "--out", r, "--check-json", c, "--bench-json", b, b2, "--quick",
         "--backend", "ref-local"])
    with open(schema_path) as f:
        schema = json.load(f)
    with open(os.path.join(r, "results.json")) as f:
        results = json.load(f)
    validator = jsonschema.Draft7Validator(schema)
    failures = []
    errors = sorted(validator.iter_errors(results), key=lambda e: list(e.path))
    for e in errors:
        failures.append("produced results.json: %s: %s" % (list(e.path), e.message))
    failures += csv_header_failures(schema, r)
    failures += bound_failures(results)
    # The parts a test of the schema must see: otherwise a null would pass for them.
    for key in ("check", "bench", "comparison", "accuracy", "gap8"):
        if results.get(key) is None:
            failures.append("produced results.json has no %s: the test would not cover it" % key)
    for what, mutate in MUTATIONS:
        broken = copy.deepcopy(results)
        try:
            mutate(broken)
        except (KeyError, IndexError, StopIteration, TypeError) as e:
            failures.append("cannot apply '%s' (%r): the file lacks what it breaks" % (what, e))
            continue
        if validator.is_valid(broken):
            failures.append("the schema accepted a copy with %s" % what)
        else:
            print("refused as it must be: %s" % what)
    for f in failures:
        print("FAIL: " + f)
    if not failures:
        print("results.json matches docs/report-schema.json; %d broken copies refused"
              % len(MUTATIONS))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
