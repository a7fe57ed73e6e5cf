#!/bin/sh
# The dut/ library (engine, framing, grid and estimate, portable kernel) for a Cortex-M4F with
# its default buffers: prints arm-none-eabi-size's table and the deepest stack frames, and fails
# when static RAM plus the deepest call chain does not leave a 20 KiB device room. With GUIDE
# (docs/PORTING.md), it also fails when the guide's numbers (its `$ sh tests/dut/mcu_size.sh`
# block and the sentence "takes N bytes of code and N bytes of RAM ... plus N bytes of stack")
# differ from these, if this compiler is the version the guide names; another version is said.
# usage: mcu_size.sh DUT_DIR OUT_DIR [GUIDE]
set -eu
dut=$1 out=$2 guide=${3:-}
mkdir -p "$out"
for f in "$dut"/src/*.c; do
  arm-none-eabi-gcc -std=c99 -pedantic -Wall -Wextra -Werror -ffreestanding -Os -mcpu=cortex-m4 \
    -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -ffp-contract=off -fstack-usage -I"$dut/include" \
    -I"$dut/../spec/include" \
    -c "$f" -o "$out/$(basename "$f" .c).o"
done
arm-none-eabi-size -t "$out"/*.o
code=$(arm-none-eabi-size -t "$out"/*.o | awk '/TOTALS/ {print $1}')
ram=$(arm-none-eabi-size -t "$out"/*.o | awk '/TOTALS/ {print $2 + $3}')
# The deepest chain: pxdut_poll (with the handlers inlined) then the kernel or the estimate (the
# spec core's pxflow_estimate_flow, which GCC may clone as .constprop.N or .isra.N). A frame not
# found fails: a renamed function must not drop out of the sum unseen.
frames=$(cat "$out"/*.su | awk -F'\t' '
  { name = $1; sub(/^.*:/, "", name); sub(/\..*$/, "", name) }
  name == "pxdut_poll" && $2 > poll {poll = $2}
  name == "pxdut_kernel_portable" && $2 > k {k = $2}
  (name == "pxdut_estimate_flow" || name == "pxflow_estimate_flow") && $2 > e {e = $2}
  END {print poll + 0, k + 0, e + 0}')
set -- $frames
if [ "$1" -eq 0 ] || [ "$2" -eq 0 ] || [ "$3" -eq 0 ]; then
  echo "mcu_size.sh: no stack frame of pxdut_poll, pxdut_kernel_portable or the estimate" \
    "(poll $1, kernel $2, estimate $3): renamed? update this script"
  exit 1
fi
stack=$(($1 + ($2 > $3 ? $2 : $3)))
echo "static RAM (data + bss): $ram bytes; deepest stack chain: $stack bytes"
test $((ram + stack)) -le 20480

[ -n "$guide" ] || exit 0
# The guide's sentences run over lines: read them as one line, thousands separators removed.
text=$(tr '\n' ' ' < "$guide" | tr -d ',')
version=$(arm-none-eabi-gcc -dumpfullversion)
documented=$(echo "$text" | sed -n 's/.*measures it with arm-none-eabi-gcc \([0-9.]*\).*/\1/p')
if [ "$version" != "$documented" ]; then
  echo "not compared with $guide: it was measured with arm-none-eabi-gcc ${documented:-?}, this is $version"
  exit 0
fi
prose=$(echo "$text" | sed -n 's/.*takes \([0-9]*\) bytes of code and \([0-9]*\) bytes of RAM.* plus \([0-9]*\) bytes of stack.*/\1 \2 \3/p')
block_totals=$(awk '/^\$ sh tests\/dut\/mcu_size.sh/ {on = 1} on && /TOTALS/ {print $1, $2 + $3; exit}' "$guide")
block_line=$(awk '/^\$ sh tests\/dut\/mcu_size.sh/ {on = 1} on && /^static RAM/ {print; exit}' "$guide")
status=0
if [ "$prose" != "$code $ram $stack" ]; then
  echo "$guide: the prose says code, RAM, stack = '$prose'; measured: $code $ram $stack"
  status=1
fi
if [ "$block_totals" != "$code $ram" ] ||
  [ "$block_line" != "static RAM (data + bss): $ram bytes; deepest stack chain: $stack bytes" ]; then
  echo "$guide: the mcu_size.sh block says '$block_totals' / '$block_line'; rerun it and paste the output"
  status=1
fi
[ $status -eq 0 ] && echo "$guide: its numbers are these (arm-none-eabi-gcc $version)"
exit $status
