#!/bin/sh
# docs/PORTING.md's buffer sizes for the whole corpus are exact: the reference device's sources
# built with the guide's -DPXDUT_MAX_PIXELS=P -DPXDUT_MAX_POIS=N run `pxflow check`'s fixed
# corpus with nothing n/a, and built with P-1 pixels, or N-1 POIs, see a case n/a. When the
# corpus grows or shrinks, this fails until the guide's numbers are the new ones (the message
# says what to look for).
# usage: device_buffer_sizes.sh GUIDE SOURCE_DIR PXFLOW OUT_DIR
set -eu
guide=$1 src=$2 pxflow=$3 out=$4
rm -rf "$out" && mkdir -p "$out"
# Every place the guide names them (its prose and its build command) must say the same.
flags=$(tr '\n' ' ' < "$guide" | grep -o -- '-DPXDUT_MAX_PIXELS=[0-9]*u -DPXDUT_MAX_POIS=[0-9]*u' |
  sort -u | sed 's/-DPXDUT_MAX_PIXELS=\([0-9]*\)u -DPXDUT_MAX_POIS=\([0-9]*\)u/\1 \2/')
if [ -z "$flags" ] || [ "$(echo "$flags" | wc -l)" -ne 1 ]; then
  echo "$guide: want one '-DPXDUT_MAX_PIXELS=Pu -DPXDUT_MAX_POIS=Nu' (found: $(echo $flags))"
  exit 1
fi
set -- $flags
pixels=$1 pois=$2

# build NAME PIXELS POIS: the reference device with these buffers (256-byte packets would do;
# large ones only make the run faster).
build() {
  cc -std=c99 -O2 -ffp-contract=off -I"$src/dut/include" -I"$src/spec/include" \
    -DPXDUT_BUILD_ID='"device_buffer_sizes"' -DPXDUT_MAX_PIXELS="$2"u -DPXDUT_MAX_POIS="$3"u \
    -DPXDUT_MAX_PACKET=16384u "$src"/dut/src/*.c "$src/dut/ref/ref_link.c" \
    "$src/dut/ref/ref_main.c" -o "$out/$1"
}
# not_applicable NAME: the row's n/a count over the fixed corpus (the row alone beside the
# reference: the row's own limit cases never are n/a for it).
not_applicable() {
  "$pxflow" check --dut "$1=exec:$out/$1" --backends "ref-original,$1" --require "$1" \
    --json "$out/$1.json" > "$out/$1.txt" || { cat "$out/$1.txt"; exit 1; }
  python3 -c 'import json, sys
rows = [r for r in json.load(open(sys.argv[1]))["backends"] if r["backend"] == sys.argv[2]]
print(rows[0]["not_applicable"])' "$out/$1.json" "$1"
}
build exact "$pixels" "$pois"
build fewer-pixels $((pixels - 1)) "$pois"
build fewer-pois "$pixels" $((pois - 1))
status=0
n=$(not_applicable exact)
if [ "$n" -ne 0 ]; then
  echo "FAIL: with $pixels pixels and $pois POIs, $n cases are n/a: the corpus needs more than" \
    "$guide says (its n/a lines:)"
  grep -i 'n/a\|larger' "$out/exact.txt" | head -5
  status=1
fi
for less in fewer-pixels fewer-pois; do
  n=$(not_applicable "$less")
  if [ "$n" -eq 0 ]; then
    echo "FAIL: $less (one less than $guide's $pixels pixels / $pois POIs) has no case n/a:" \
      "the corpus needs less than the guide says"
    status=1
  fi
done
[ $status -eq 0 ] &&
  echo "ok: $pixels pixels and $pois POIs run the whole corpus, one pixel or one POI less does not"
exit $status
