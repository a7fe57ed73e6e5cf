#!/bin/sh
# pxflow compare --run OLD NEW, end to end (docs/harness.md, "Two builds, interleaved"):
#   A/A   the same binary on both sides must never fail the gate (the 1.91x false alarm of
#         1261786 was two runs of one build): exit 0 (passed) or 3 (inconclusive).
#   A/B   B with a planted 100 % slowdown (PXFLOW_BENCH_PLANTED_SLOWDOWN: twice the batches run
#         per counted frame) must fail a 20 % gate: exit 1. When the machine was disturbed or so
#         noisy that the interval still holds 1.2, the gate rightly cannot decide: the test is
#         then skipped (exit 77, CTest's "skipped"), saying why; it never passes then.
# Usage: compare_run_gate.sh PXFLOW
set -u
pxflow=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
bench="--backends ref-local --batch 2 --sizes 64x64 --min-time 0.1 --no-bound"

"$pxflow" compare --run "$pxflow" "$pxflow" --rounds 5 --fail-above 5 --bench-args "$bench" \
  >"$dir/aa.txt" 2>&1
rc=$?
if [ "$rc" != 0 ] && [ "$rc" != 3 ]; then
  cat "$dir/aa.txt"
  echo "FAIL: A/A (one binary on both sides) exited $rc; expected 0 (passed) or 3 (inconclusive)"
  exit 1
fi

printf '#!/bin/sh\nPXFLOW_BENCH_PLANTED_SLOWDOWN=100 exec "%s" "$@"\n' "$pxflow" >"$dir/planted"
chmod +x "$dir/planted"
"$pxflow" compare --run "$pxflow" "$dir/planted" --rounds 8 --fail-above 20 \
  --bench-args "$bench" --out "$dir/ab" >"$dir/ab.txt" 2>&1
rc=$?
if [ "$rc" = 1 ] && grep -q ' 1 failed' "$dir/ab.txt"; then
  echo "passed: A/A did not fail; the planted 100 % slowdown failed the 20 % gate"
  exit 0
fi
if [ "$rc" = 3 ]; then
  grep -E '^warning|inconclusive' "$dir/ab.txt"
  echo "SKIPPED: the gate could not decide on this machine now (above: why); not a pass"
  exit 77
fi
cat "$dir/ab.txt"
echo "FAIL: the planted 100 % slowdown did not fail the 20 % gate (exit $rc)"
exit 1
