"""The campaign's results: results.json (every mutant) and results.md (the tables, the survivors).

Written after every mutant (to a temporary, then renamed), so a stopped campaign keeps what ran.
"""

import json
import os

COLUMNS = ("mutants", "compiled", "equivalent", "killed", "survived", "build-failed", "not-run")


def _count(results):
    c = dict.fromkeys(COLUMNS, 0)
    for r in results:
        c["mutants"] += 1
        c[r["status"]] += 1
    c["compiled"] = c["equivalent"] + c["killed"] + c["survived"]
    return c


def _score(c):
    judged = c["killed"] + c["survived"]
    return f"{100.0 * c['killed'] / judged:.1f} %" if judged else "-"


def _table(title, groups):
    lines = [f"| {title} | " + " | ".join(COLUMNS) + " | killed of non-equivalent |",
             "|---" * (len(COLUMNS) + 2) + "|"]
    for name, results in groups:
        c = _count(results)
        lines.append(f"| {name} | " + " | ".join(str(c[k]) for k in COLUMNS) + f" | {_score(c)} |")
    return lines


def markdown(meta, results, seconds):
    by_file, by_family = {}, {}
    for r in results:
        by_file.setdefault((r["family"], r["path"], ",".join(r["rows"])), []).append(r)
        by_family.setdefault(r["family"], []).append(r)
    out = [f"# Mutation campaign: seed {meta['seed']}, {meta['per_family']} per family",
           "", f"`{meta['command']}`: {len(results)} mutants in {seconds / 60:.1f} min.", ""]
    out += _table("family", sorted(by_family.items()) + [("**total**", results)])
    out += [""]
    out += _table("file (rows)", [(f"{p} ({rows})", rs) for (_, p, rows), rs in sorted(by_file.items())])
    survivors = [r for r in results if r["status"] == "survived"]
    out += ["", f"## Survivors ({len(survivors)})", ""]
    for r in survivors:
        out += [f"- `{r['id']}` ({','.join(r['rows'])})", "", "```diff", r["diff"], "```", ""]
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
