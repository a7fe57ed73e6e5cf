"""The campaign's results: results.json (every mutant) and results.md (the tables, the survivors).

Written after every mutant (to a temporary, then renamed), so a stopped campaign keeps what ran.
"""

import json
import os

# killed: by the default `pxflow check`; killed-sanitizer: only by the family's test of .ci/run's
# ASan+UBSan stage; killed-oclgrind: only by .ci/run's Oclgrind test (opencl_memcheck_oclgrind,
# tests/opencl/oclgrind_check.sh); both are targets.Family.memory_test; undetectable: a survivor
# reviewed as invisible to any check on this machine (undetectable.txt), never counted as killed.
KILLED = ("killed", "killed-sanitizer", "killed-oclgrind")
COLUMNS = ("mutants", "compiled", "equivalent", *KILLED, "undetectable", "survived", "build-failed",
           "not-run")
HEADINGS = {"killed-sanitizer": "killed (sanitizer)", "killed-oclgrind": "killed (Oclgrind)",
            "undetectable": "undetectable here"}


def _count(results):
    c = dict.fromkeys(COLUMNS, 0)
    for r in results:
        c["mutants"] += 1
        c[r["status"]] += 1
    c["compiled"] = c["equivalent"] + sum(c[k] for k in KILLED) + c["undetectable"] + c["survived"]
    return c


def _score(c, kinds):
    """The share of the non-equivalent mutants killed by `kinds`."""
    judged = sum(c[k] for k in KILLED) + c["undetectable"] + c["survived"]
    return f"{100.0 * sum(c[k] for k in kinds) / judged:.1f} %" if judged else "-"


def _table(title, groups):
    lines = [f"| {title} | " + " | ".join(HEADINGS.get(k, k) for k in COLUMNS)
             + " | killed by the default check, of non-equivalent"
             + " | killed by the default corpus with its memory checkers, of non-equivalent |",
             "|---" * (len(COLUMNS) + 3) + "|"]
    for name, results in groups:
        c = _count(results)
        lines.append(f"| {name} | " + " | ".join(str(c[k]) for k in COLUMNS)
                     + f" | {_score(c, ('killed',))} | {_score(c, KILLED)} |")
    return lines


def markdown(meta, results, seconds):
    by_file, by_family = {}, {}
    for r in results:
        by_file.setdefault((r["family"], r["path"], ",".join(r["rows"])), []).append(r)
        by_family.setdefault(r["family"], []).append(r)
    title = (f"# Mutation rerun: the mutants --only {meta['only']} names" if meta.get("only")
             else f"# Mutation campaign: seed {meta['seed']}, {meta['per_family']} per family")
    out = [title,
           "", f"`{meta['command']}`: {len(results)} mutants in {seconds / 60:.1f} min.", ""]
    out += _table("family", sorted(by_family.items()) + [("**total**", results)])
    out += [""]
    out += _table("file (rows)", [(f"{p} ({rows})", rs) for (_, p, rows), rs in sorted(by_file.items())])
    for status, title in (("survived", "Survivors"), ("killed-sanitizer", "Killed only under ASan+UBSan"),
                          ("killed-oclgrind", "Killed only under Oclgrind"),
                          ("undetectable", "Undetectable here (tests/mutation/undetectable.txt)")):
        listed = [r for r in results if r["status"] == status]
        out += ["", f"## {title} ({len(listed)})", ""]
        for r in listed:
            note = f": {r['detail']}" if r.get("detail") else ""
            out += [f"- `{r['id']}` ({','.join(r['rows'])}){note}", "", "```diff", r["diff"], "```", ""]
    reviewed = [r for r in results if r["status"] == "equivalent" and r["detail"].startswith("reviewed")]
    out += [f"## Equivalent by review ({len(reviewed)}, tests/mutation/equivalent.txt)", ""]
    out += [f"- `{r['id']}`: {r['detail'][len('reviewed: '):]}" for r in reviewed]
    return "\n".join(out) + "\n"


def _replace(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


def write(folder, meta, results, seconds):
    doc = dict(meta, seconds=round(seconds, 1), totals=_count(results), mutants=results)
    _replace(os.path.join(folder, "results.json"), json.dumps(doc, indent=1) + "\n")
    _replace(os.path.join(folder, "results.md"), markdown(meta, results, seconds))
