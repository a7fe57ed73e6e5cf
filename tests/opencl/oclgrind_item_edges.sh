#!/bin/sh
# oclgrind_item_edges.sh PXFLOW OPENCL_CL PARAMS_H: the opencl-item row under Oclgrind at its own
# edges, whatever the corpus selects: SPEC's largest radius (PXFLOW_MAX_RADIUS of the spec core's
# params.h, 31: the lanes search's private arrays at their full size) and the lanes search's first
# radius (LANES_MIN_RADIUS of the kernel source), both read from their sources so that a moved
# value is followed; one POI each on an 80x80 pair (a window of 2S + 8 = 70 pixels fits). The
# generated cases of opencl_memcheck_oclgrind run S = 4 only, which never reaches that search.
set -u
if [ $# -ne 3 ]; then
  echo "usage: oclgrind_item_edges.sh PXFLOW OPENCL_CL PARAMS_H" >&2
  exit 2
fi
pxflow=$1
lanes_min=$(sed -n 's/^#define LANES_MIN_RADIUS \([0-9][0-9]*\).*/\1/p' "$2")
max_radius=$(sed -n 's/^#define PXFLOW_MAX_RADIUS \([0-9][0-9]*\)u*$/\1/p' "$3")
if [ -z "$lanes_min" ] || [ -z "$max_radius" ]; then
  echo "oclgrind_item_edges.sh: no LANES_MIN_RADIUS in $2 or no PXFLOW_MAX_RADIUS in $3" >&2
  exit 2
fi
dir=$(mktemp -d) || exit 2
trap 'rm -rf "$dir"' EXIT
# Two 80x80 frames of a fixed pseudo-random texture, the second shifted by 3 pixels.
python3 -c '
import random, sys
rng = random.Random(7)
tex = [bytes(rng.randrange(256) for _ in range(83)) for _ in range(80)]
open(sys.argv[1], "wb").write(b"".join(r[:80] for r in tex))
open(sys.argv[2], "wb").write(b"".join(r[3:] for r in tex))
' "$dir/a.raw" "$dir/b.raw" || exit 2
status=0
for s in "$max_radius" "$lanes_min"; do
  echo "S = $s:"
  "$(dirname "$0")/oclgrind_check.sh" "$pxflow" flow --backend opencl-item --size 80x80 \
    --set search_radius="$s" --set blocks=1 "$dir/a.raw" "$dir/b.raw"
  rc=$?
  [ $rc -eq 77 ] && exit 77  # no oclgrind: skipped, as oclgrind_check.sh says
  [ $rc -ne 0 ] && status=1
done
exit $status
