#!/bin/sh
# The corpus against vector ports' bugs (docs/check-corpus.md, "Every row at its own edges"): a
# device that searches in chunks of L candidates (tests/dut/pxdut_vector_port.c) is checked alone,
# `pxflow check --backends ref-original,port`, the default fixed corpus. A correct port must pass at
# every L; each bug must fail at every L: the chunk base dropped, the tail mask one lane too long
# and too short, the half-pixel lanes swapped. Chunks over a window row at L = 8, 16, 32, 64, and
# over the flattened window as an SVE port does (svcnth(): 32 lanes at 512 bits, 128 at 2048).
# L = 64 over a row is the one equivalent port: 2S+1 <= 63 candidates fit one chunk, so a dropped
# chunk base never shows at any legal S; it must pass. The flattened window's ports and a correct
# port run the whole default corpus; the others its limit cases alone (--limits-only, a subset of
# it: what they fail, the default check fails too), to keep this test short.
# Usage: vector_port_check.sh PXFLOW PXDUT-VECTOR-PORT
set -u
pxflow=$1
device=$2
failed=0
out=$(mktemp)
trap 'rm -f "$out"' EXIT
run() {  # LANES CHUNKS BUG EXPECTED-EXIT [--limits-only]
  "$pxflow" check --dut "port=exec:$device $1 $2 $3" --backends ref-original,port --require port \
    --no-repro ${5:-} >"$out" 2>&1
  rc=$?
  verdict=$(grep -E '^[0-9]+ passed' "$out" | tail -1)
  if [ "$rc" = "$4" ]; then
    echo "ok    L=$1 $2 $3 ${5:-(default corpus)}: exit $rc ($verdict)"
  else
    echo "FAIL  L=$1 $2 $3 ${5:-(default corpus)}: exit $rc, expected $4 ($verdict)"
    tail -5 "$out"
    failed=1
  fi
}
run 32 flat none 0
run 32 row chunk-base 1
for lanes in 32 64 128; do run $lanes flat chunk-base 1; done
for lanes in 8 16 32 64; do
  run $lanes row none 0 --limits-only
  for bug in tail-over tail-under half-lanes; do run $lanes row $bug 1 --limits-only; done
done
for lanes in 8 16; do run $lanes row chunk-base 1 --limits-only; done
run 64 row chunk-base 0 --limits-only
for lanes in 8 16; do run $lanes flat chunk-base 1 --limits-only; done
run 128 flat none 0 --limits-only
exit $failed
