#!/usr/bin/env bash
# The Release suite under stress: CTest at twice the core count while a CPU hog keeps every core
# busy, RUNS times in a row (default 3); it passes only when every run passes. Not part of
# .ci/run: a check that the tests hold on a loaded machine (slow is not hung), with its times in
# docs/test-suite.md ("The suite under stress").
#
#   bash ci/stress-tests.sh [RUNS [BUILD_DIR]]
#
# The hog is one busy shell loop per core at normal priority, started before the first run and
# stopped on every way out of this script (the end, a failure, Ctrl-C, SIGTERM).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
runs=${1:-3}
build=${2:-"$root/build"}
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "stress-tests: RUNS must be a positive integer, not '$runs'" >&2; exit 2; }
cores=$(nproc)

"$root/ci/build.sh" "$build"

hogs=()
stop_hogs() {
  [ ${#hogs[@]} -eq 0 ] && return 0
  kill "${hogs[@]}" 2>/dev/null || true
  wait "${hogs[@]}" 2>/dev/null || true
  hogs=()
}
trap stop_hogs EXIT
trap 'stop_hogs; exit 130' INT
trap 'stop_hogs; exit 143' TERM
for _ in $(seq "$cores"); do
  (trap - INT TERM; while :; do :; done) &
  hogs+=($!)
done
echo "== stress: ${#hogs[@]} busy loops on $cores cores; ctest -j$((2 * cores)), $runs runs"

for run in $(seq "$runs"); do
  start=$(date +%s)
  load_before=$(cut -d' ' -f1 /proc/loadavg)
  status=0
  ctest --test-dir "$build" -j$((2 * cores)) --output-on-failure --timeout 1500 \
    --output-junit "$build/stress-$run.xml" >"$build/stress-$run.log" 2>&1 || status=$?
  seconds=$(($(date +%s) - start))
  summary=$(python3 "$root/ci/test-summary.py" "stress run $run" "$build/stress-$run.xml" "$seconds s")
  echo "$summary (load average $load_before at the start; log: $build/stress-$run.log)"
  if [ "$status" -ne 0 ]; then
    grep -E '\*\*\*(Failed|Timeout|Exception)|Failed  |Timeout' "$build/stress-$run.log" || true
    echo "stress-tests: run $run of $runs failed" >&2
    exit 1
  fi
done
echo "stress-tests: $runs of $runs runs passed under the hog"
