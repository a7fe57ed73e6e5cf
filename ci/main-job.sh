#!/usr/bin/env bash
# The main job: set up, build, then the cross-check of every backend on the full corpus (real
# frames from Debian's opencv-doc, synthetic motion, random, hostile and threshold cases), and
# the performance report in out/report (report.md, report.html, results.json, results.csv).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
PXFLOW_BUILD_TARGET=pxflow "$root/ci/build.sh" "$root/build"
pxflow="$root/build/pxflow"

mkdir -p "$root/out"
"$pxflow" backends
echo
"$pxflow" check --json "$root/out/check.json" || status=$?
echo
"$pxflow" report --out "$root/out/report" --check-json "$root/out/check.json"
exit "${status:-0}"
