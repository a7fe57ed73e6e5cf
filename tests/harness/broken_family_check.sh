#!/usr/bin/env bash
# pxflow check gives a verdict whatever a backend does: the broken family's rows (each
# ref-original with one fault, tests/harness/broken_family) each get their own failure line,
# dummy-original (a correct row) still passes, the summary prints and the check exits 1.
# --case-timeout 5: the hang's default allowance is a minute at least (docs/harness.md,
# "Isolation"); every other case here takes well under a second.
# Usage: broken_family_check.sh PXFLOW (the one_call_family build's binary)
set -uo pipefail
pxflow=$1
rows=ref-original,dummy-original,broken-crash,broken-abort,broken-hang,broken-overrun
rows+=,broken-underrun,broken-overread,broken-miscount
out=$("$pxflow" check --generated-only --case-timeout 5 --backends "$rows" 2>&1)
code=$?
echo "$out"
fail() { echo "FAIL: $*" >&2; exit 1; }
[ "$code" = 1 ] || fail "exit status $code, not 1"
expect() {  # a line of the output matching the extended regular expression $1
  grep -Eq -- "$1" <<<"$out" || fail "no line matching: $1"
}
case_of="case=random\[[^]]*\]"
# The crash in case 0 and again in case 4: the row went on in a fresh worker.
for n in 0 4; do
  expect "^FAIL broken-crash $case_of killed by SIGSEGV in case $n 'random' pair [0-9]+ 'random/[^']+'$"
done
expect "^FAIL broken-abort $case_of killed by SIGABRT in case 0 'random' pair 0 '[^']+'$"
expect "^FAIL broken-hang case=random\[320x240 S=7 B=16\] did not finish case 8 'random' within 5 s \(--case-timeout\)$"
expect "^FAIL broken-overrun $case_of wrote past its output \([0-9]+ bytes after record [0-9]+\)$"
expect "^FAIL broken-underrun $case_of wrote before its output \([0-9]+ bytes before record 0\)$"
expect "^FAIL broken-overread $case_of killed by SIGSEGV in case 0 'random' pair 0 '[^']+': it read 1 byte past the end of the next frame of the pair \(strict input\)$"
# Counts are part of the check (docs/counting.md): one SAD operation too many fails the case.
expect "^FAIL broken-miscount $case_of counts differ from ref-original's: sad_ops [0-9,]+ vs [0-9,]+ "
for row in crash abort hang overrun underrun overread miscount; do
  expect "^broken-$row +failed "
done
expect "^dummy-original +passed "
expect "^[0-9]+ passed, [0-9]+ failed, 0 skipped$"
echo "check isolates broken rows: ok"
