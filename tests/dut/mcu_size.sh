#!/bin/sh
# The dut/ library (engine, framing, grid and estimate, portable kernel) for a Cortex-M4F with
# its default buffers: prints arm-none-eabi-size's table and the deepest stack frames, and fails
# when static RAM plus the deepest call chain does not leave a 20 KiB device room.
# usage: mcu_size.sh DUT_DIR OUT_DIR
set -eu
dut=$1 out=$2
mkdir -p "$out"
for f in "$dut"/src/*.c; do
  arm-none-eabi-gcc -std=c99 -pedantic -Wall -Wextra -Werror -ffreestanding -Os -mcpu=cortex-m4 \
    -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -ffp-contract=off -fstack-usage -I"$dut/include" \
    -I"$dut/../spec/include" \
    -c "$f" -o "$out/$(basename "$f" .c).o"
done
arm-none-eabi-size -t "$out"/*.o
ram=$(arm-none-eabi-size -t "$out"/*.o | awk '/TOTALS/ {print $2 + $3}')
# The deepest chain: pxdut_poll (with the handlers inlined) then the kernel or the estimate.
stack=$(cat "$out"/*.su | awk -F'\t' '
  $1 ~ /:pxdut_poll$/ {poll = $2}
  $1 ~ /:pxdut_kernel_portable$/ {k = $2}
  $1 ~ /:pxdut_estimate_flow$/ {e = $2}
  END {print poll + (k > e ? k : e)}')
echo "static RAM (data + bss): $ram bytes; deepest stack chain: $stack bytes"
test $((ram + stack)) -le 20480
