#!/usr/bin/env bash
# Renders a freshly made report.html in headless Chromium: the page must load without console
# errors, contain its charts, and produce a screenshot. Usage: report_in_chromium.sh PXFLOW OUTDIR
set -euo pipefail
pxflow=$1 out=$2
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "SKIP: chromium not installed (ci/packages.txt lists it; run ci/install-deps.sh)"
  exit 77
fi
rm -rf "$out" && mkdir -p "$out"
"$pxflow" report --out "$out" --quick --backends ref-original,ref-local >"$out.log"
for f in report.md report.html results.json results.csv; do
  [ -s "$out/$f" ] || { echo "FAIL: $f missing or empty"; exit 1; }
done
flags=(--headless --no-sandbox --disable-gpu --hide-scrollbars --enable-logging=stderr --v=0)
timeout 600 "$browser" "${flags[@]}" --window-size=1100,2400 --screenshot="$out/report.png" \
  "file://$out/report.html" 2>"$out/chromium.log" || { cat "$out/chromium.log"; exit 1; }
[ -s "$out/report.png" ] || { echo "FAIL: no screenshot"; exit 1; }
if grep -E "CONSOLE|Uncaught|Failed to load resource|net::ERR" "$out/chromium.log"; then
  echo "FAIL: the page logged errors"; exit 1
fi
dom=$(timeout 600 "$browser" "${flags[@]}" --dump-dom "file://$out/report.html" 2>/dev/null)
charts=$(grep -o "<svg" <<<"$dom" | wc -l)
[ "$charts" -ge 3 ] || { echo "FAIL: expected >= 3 charts in the rendered page, found $charts"; exit 1; }
grep -q "Conformance" <<<"$dom" || { echo "FAIL: conformance section missing"; exit 1; }
# Provenance comes first: the build's commit and the backends' descriptions before any result.
commit=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["provenance"]["build"]["commit"])' "$out/results.json")
head=${dom%%id=\"conformance\"*}
for want in "id=\"provenance\"" "commit $commit" "What each backend runs" "ref-local"; do
  grep -qF "$want" <<<"$head" || { echo "FAIL: '$want' not before the conformance section"; exit 1; }
done
# A comparison of two bench files: the report's own bench, and a copy with its first row's samples
# 20 % slower (docs/harness.md, "Comparing bench files"), rendered with its chart and verdict.
python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
results = json.load(open(out + "/results.json"))
json.dump(results["check"], open(out + "/c.json", "w"))
# The row's five process medians set 1 % apart around its median first, the machine quiet: what
# is shown is the comparison, not how quiet this machine was.
row = next(r for r in results["bench"]["rows"] if "samples_ns_per_frame" in r)
median = row["median_ns_per_frame"]
results["bench"]["machine"]["disturbed"] = ""
for name, factor in (("a.json", 1.0), ("b.json", 1.2)):
    m = median * factor
    row["samples_ns_per_frame"] = [m * (1 + k / 100) for k in (-2, -1, 0, 1, 2)]
    row["process_medians_ns_per_frame"] = row["samples_ns_per_frame"]
    row["processes"] = 5
    row["median_ns_per_frame"] = m
    row["median_ci_low_ns"], row["median_ci_high_ns"] = m * 0.98, m * 1.02
    json.dump(results["bench"], open(out + "/" + name, "w"))
PY
"$pxflow" report --out "$out/compare" --check-json "$out/c.json" --bench-json "$out/a.json" \
  "$out/b.json" --no-accuracy --backends ref-original,ref-local >"$out.compare.log"
timeout 600 "$browser" "${flags[@]}" --window-size=1100,2400 --screenshot="$out/compare.png" \
  "file://$out/compare/report.html" 2>"$out/chromium-compare.log" || { cat "$out/chromium-compare.log"; exit 1; }
if grep -E "CONSOLE|Uncaught|Failed to load resource|net::ERR" "$out/chromium-compare.log"; then
  echo "FAIL: the comparison page logged errors"; exit 1
fi
dom=$(timeout 600 "$browser" "${flags[@]}" --dump-dom "file://$out/compare/report.html" 2>/dev/null)
tail=${dom#*id=\"comparison\"}
[ "$tail" != "$dom" ] || { echo "FAIL: no comparison section"; exit 1; }
grep -q "<svg" <<<"$tail" || { echo "FAIL: the comparison has no chart"; exit 1; }
grep -qF 'id="comparison-b"' <<<"$tail" || { echo "FAIL: no section for file B"; exit 1; }
grep -qF "<td class=\"\">slower</td>" <<<"$tail" || { echo "FAIL: the planted slowdown is not shown"; exit 1; }
echo "report renders: $charts charts, screenshot $out/report.png; comparison $out/compare.png"
