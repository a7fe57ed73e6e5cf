#!/bin/sh
# oclgrind_item_edges.sh PXFLOW OPENCL_CL: the opencl-item row under Oclgrind at its own edges,
# whatever the corpus selects: SPEC's largest radius (S = 31, the lanes search's private arrays
# at their full size) and the first radius of the lanes search (LANES_MIN_RADIUS, read from the
# kernel source, so a moved threshold is followed), one POI each on an 80x80 pair. The generated
# cases of opencl_memcheck_oclgrind run S = 4 only, which never reaches that search.
set -u
if [ $# -ne 2 ]; then
  echo "usage: oclgrind_item_edges.sh PXFLOW OPENCL_CL" >&2
  exit 2
fi
pxflow=$1
lanes_min=$(sed -n 's/^#define LANES_MIN_RADIUS \([0-9][0-9]*\).*/\1/p' "$2")
if [ -z "$lanes_min" ]; then
  echo "oclgrind_item_edges.sh: no LANES_MIN_RADIUS in $2" >&2
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
for s in 31 "$lanes_min"; do
  echo "S = $s:"
  "$(dirname "$0")/oclgrind_check.sh" "$pxflow" flow --backend opencl-item --size 80x80 \
    --set search_radius="$s" --set blocks=1 "$dir/a.raw" "$dir/b.raw" || status=1
done
exit $status
