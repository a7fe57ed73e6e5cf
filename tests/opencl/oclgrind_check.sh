#!/bin/sh
# oclgrind_check.sh PXFLOW [flow] [check or flow options...]: `pxflow check` (or `pxflow flow`) with
# its OpenCL rows run by Oclgrind
# (Debian's oclgrind: a simulator that checks every access of a kernel to global, local and
# private memory), the memory checker of OpenCL C as ASan+UBSan is of host code. Prints the
# check's output; any error Oclgrind reports (an access outside a buffer or an array, a local
# write past an array into the next one) becomes a "FAIL oclgrind: ..." line and exit 1, even
# when the records come out right. Exit 77 when oclgrind is not installed.
# Used by the test opencl_memcheck_oclgrind and by tests/mutation/mutate.py's memory-checker pass.
set -u
if [ $# -lt 1 ]; then
  echo "usage: oclgrind_check.sh PXFLOW [flow] [check or flow options...]" >&2
  exit 2
fi
pxflow=$1
shift
command=check
if [ "${1:-}" = flow ]; then
  command=flow
  shift
fi
if ! command -v oclgrind >/dev/null 2>&1; then
  echo "oclgrind_check.sh: oclgrind is not installed (ci/packages.txt lists it)" >&2
  exit 77
fi
log=$(mktemp) || exit 2
trap 'rm -f "$log"' EXIT
oclgrind --log "$log" "$pxflow" "$command" "$@"
status=$?
if [ -s "$log" ]; then
  reports=$(grep -c -E '^(Invalid|Uninitialized|Work-group|Data race|Read-write|Write-write)' "$log")
  first=$(grep -m 1 -v -E '^[[:space:]]*$' "$log")
  echo "FAIL oclgrind: $first ($reports reports; the log's first lines follow)"
  grep -v -E '^[[:space:]]*$' "$log" | head -n 12
  exit 1
fi
exit "$status"
