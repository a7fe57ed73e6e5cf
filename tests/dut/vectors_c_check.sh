#!/bin/sh
# `pxflow vectors --format c` as a firmware engineer uses it: the C output compiles freestanding
# (-ffreestanding -Werror, and for a Cortex-M4 when arm-none-eabi-gcc is there), and a unit test
# built from it passes with dut/'s portable kernel (vectors_main.c), on the host.
# usage: vectors_c_check.sh PXFLOW SOURCE_DIR OUT_DIR
set -eu
pxflow=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
"$pxflow" vectors --out "$out" --format c --cases 24 --seed 3
for f in pxflow_vectors.c pxflow_vectors_check.c; do
  cc -std=c99 -pedantic -Wall -Wextra -Werror -ffreestanding -c "$out/$f" -o "$out/$f.o"
  if command -v arm-none-eabi-gcc > /dev/null; then
    arm-none-eabi-gcc -std=c99 -pedantic -Wall -Wextra -Werror -ffreestanding -Os \
      -mcpu=cortex-m4 -mthumb -c "$out/$f" -o "$out/$f.m4.o"
  fi
done
cc -std=c99 -ffp-contract=off -I"$out" -I"$src/dut/include" -I"$src/spec/include" "$src/tests/dut/vectors_main.c" \
  "$out/pxflow_vectors.c" "$out/pxflow_vectors_check.c" "$src/dut/src/pxdut_kernel.c" \
  "$src/dut/src/pxdut_grid.c" -o "$out/vectors_test"
"$out/vectors_test"
