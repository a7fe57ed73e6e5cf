#!/usr/bin/env bash
# The main job: set up, build, and run pxflow on its default data (real frames from Debian's
# opencv-doc): the frame estimate of every backend that can run here, then the list of backends.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/ci/build.sh" "$root/build"
pxflow="$root/build/pxflow"
data=/usr/share/doc/opencv-doc/examples/data

"$pxflow" backends
for backend in $("$pxflow" backends | awk 'NR > 1 && $2 == "available" {print $1}'); do
  for pair in rubberwhale basketball; do
    echo
    "$pxflow" flow --backend "$backend" "$data/${pair}1.png" "$data/${pair}2.png"
  done
done
