#!/usr/bin/env bash
# The packages (cmake/PxflowPackage.cmake): cpack makes the tarball and the .deb of this build; the
# tarball is unpacked into a temporary folder and run from there with the build and source trees
# hidden (a private mount namespace mounts an empty folder over each; without the privilege for
# that, they stay visible and the test says so) and a minimal environment: env -i, HOME in the
# temporary folder, PATH = the tarball's bin/ and a folder of links to the machine programs that
# rows drive, never pxflow's: ld (PoCL links kernels with it) and qemu-system-arm (the m4-qemu
# row). Then check (a short fuzz campaign on every kind of row, the DUT reference as a device),
# bench, and flow on real frames, which loads the OpenCV module from the tarball's lib/pxflow.
# Usage: package.sh BUILD_DIR SOURCE_DIR CPACK
set -euo pipefail
build=$1 source=$2 cpack=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$cpack" --config "$build/CPackConfig.cmake" -B "$tmp/pkg" > "$tmp/cpack.log" 2>&1 ||
  { cat "$tmp/cpack.log"; fail "cpack failed"; }
tarball=$(ls "$tmp"/pkg/pxflow-*.tar.gz) || fail "no tarball in $tmp/pkg"
deb=$(ls "$tmp"/pkg/pxflow_*.deb) || fail "no .deb in $tmp/pkg"
echo "made $(basename "$tarball") and $(basename "$deb")"

# The .deb: the tree under /usr, its libraries named as Debian packages.
depends=$(dpkg-deb -f "$deb" Depends)
echo ".deb Depends: $depends"
for package in ocl-icd-libopencl1 libvulkan1 libelf1 libstdc++6; do
  grep -q "$package" <<< "$depends" || fail ".deb does not depend on $package"
done
contents=$(dpkg-deb -c "$deb")
for file in ./usr/bin/pxflow ./usr/bin/gap8-run ./usr/bin/pxflow-dut-ref \
    ./usr/lib/pxflow/libpxflow_opencv.so ./usr/share/pxflow/pxflow_m4_dut.elf \
    ./usr/share/man/man1/pxflow-check.1; do
  grep -q " $file\$" <<< "$contents" || fail ".deb lacks $file"
done
if grep -q "libOpenCL.so\|libvulkan.so" <<< "$contents"; then fail ".deb bundles a loader"; fi

# The tarball: one folder, the loaders bundled, the programs looking in ../lib first.
mkdir "$tmp/unpacked" "$tmp/home" "$tmp/tools" "$tmp/empty" "$tmp/out"
tar -xzf "$tarball" -C "$tmp/unpacked"
root=$(ls -d "$tmp"/unpacked/pxflow-*)
for lib in libOpenCL.so.1 libvulkan.so.1 libstdc++.so.6; do
  [[ -f $root/lib/$lib ]] || fail "the tarball does not bundle $lib"
done
# Each tool's whole output first: `tool | grep -q` under pipefail fails when grep, done at its
# first match, leaves the tool writing to a closed pipe (SIGPIPE), a race.
dynamic=$(readelf -d "$root/bin/pxflow")
grep -q 'RUNPATH.*\[\$ORIGIN/../lib\]' <<<"$dynamic" ||
  fail "bin/pxflow does not look in \$ORIGIN/../lib"
loads=$(ldd "$root/bin/pxflow")
grep -q "libOpenCL.so.1 => $root/bin/../lib/libOpenCL.so.1" <<<"$loads" ||
  fail "bin/pxflow does not load the bundled OpenCL loader: $loads"
for program in ld qemu-system-arm; do
  ln -s "$(command -v "$program")" "$tmp/tools/$program"
done

# Runs "$@" in the minimal environment, with the trees hidden where the namespace can be made.
hide="mount --bind '$tmp/empty' '$build' && mount --bind '$tmp/empty' '$source'"
if unshare -m --propagation private true 2> /dev/null; then
  echo "build and source trees hidden (unshare -m)"
  run() { unshare -m --propagation private sh -c "$hide && cd '$tmp/out' && exec \"\$@\"" run \
    env -i HOME="$tmp/home" PATH="$root/bin:$tmp/tools" "$@"; }
else
  echo "note: build and source trees left visible (unshare -m needs root); environment minimal"
  run() { (cd "$tmp/out" && env -i HOME="$tmp/home" PATH="$root/bin:$tmp/tools" "$@"); }
fi

run pxflow check --cases 12 --seed 3 --backends ref-original,cpu,opencl,vulkan,gap8-fast,m4-qemu,ref \
  --require cpu,opencl,vulkan,gap8-fast,m4-qemu,ref --dut ref=exec:pxflow-dut-ref \
  --json check.json > "$tmp/check.log" 2>&1 || { cat "$tmp/check.log"; fail "check failed"; }
tail -n 3 "$tmp/check.log"
grep -q "^m4-qemu  *passed" "$tmp/check.log" || fail "m4-qemu did not pass (firmware not found?)"
run pxflow bench --backends cpu,gap8-fast --batch 1 --sizes 64x64 --min-time 0.05 \
  --json bench.json > "$tmp/bench.log" 2>&1 || { cat "$tmp/bench.log"; fail "bench failed"; }
[[ -s $tmp/out/bench.json ]] || fail "bench wrote no bench.json"
data=/usr/share/doc/opencv-doc/examples/data
run pxflow flow --backend cpu "$data/rubberwhale1.png" "$data/rubberwhale2.png" \
  > "$tmp/flow.log" 2>&1 || { cat "$tmp/flow.log"; fail "flow on real frames failed"; }
head -n 2 "$tmp/flow.log"
echo "the tarball ran check, bench and flow from $root"
