#!/bin/sh
# Builds the DUT wire fuzzer with clang (libFuzzer, ASan, UBSan) and runs it.
# usage: fuzz_dut_wire.sh SOURCE_DIR OUT_DIR [libFuzzer options, e.g. -max_total_time=30]
# Exit 0 when the run ended without a crash, leak or timeout (libFuzzer's own exit otherwise).
set -eu
src=$1 out=$2
shift 2
mkdir -p "$out/corpus"
flags="-g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all"
clang -std=c99 $flags -I"$src/dut/include" -I"$src/spec/include" -c "$src/dut/src/pxdut_framing.c" -o "$out/framing.o"
clang++ -std=c++20 $flags -I"$src/dut/include" -I"$src/spec/include" -I"$src/hosts/dut" \
  -I"$src/hosts/core" -I"$src/reference" \
  "$src/tests/dut/fuzz_dut_wire.cpp" "$src/hosts/dut/dut_wire.cpp" "$out/framing.o" \
  -o "$out/fuzz_dut_wire"
# One seed, an empty COBS frame; libFuzzer finds delimiters, codes and CRCs from there.
printf '\001\001\000' > "$out/corpus/seed-empty"
exec "$out/fuzz_dut_wire" -timeout=5 -rss_limit_mb=1024 "$@" "$out/corpus"
