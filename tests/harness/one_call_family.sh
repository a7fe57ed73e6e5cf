#!/usr/bin/env bash
# The one-CMake-call claim, tested: a build that adds tests/harness/dummy_family (one
# pxflow_backend_family() call, a copy of ref-original) through PXFLOW_EXTRA_FAMILY_DIRS, with no
# other file edited, lists its row in `pxflow backends` and passes `pxflow check` with it
# required; a required family whose SDK is missing fails the configure; one that is not
# required is off with its reason. The same build adds tests/harness/broken_family, whose rows
# broken_family_check.sh checks (the fixture one_call_build: one extra build, not two).
# Usage: one_call_family.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
# -O1: the test proves what the build contains, not how fast it runs; -O1 compiles in about
# half -O3's time (docs/test-suite.md, "The test suite's time"). ccache, when installed, comes from
# the project's own settings (cmake/PxflowCcache.cmake: another clone hits the cache).
common=(-S "$src" -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS=-O1 -DCMAKE_C_FLAGS=-O1 -DBUILD_TESTING=OFF -DPXFLOW_WITH_ALL=OFF
        -DPXFLOW_WITH_DUMMY=ON -DPXFLOW_WITH_BROKEN=ON
        "-DPXFLOW_EXTRA_FAMILY_DIRS=$src/tests/harness/dummy_family;$src/tests/harness/broken_family")
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake "${common[@]}" -B "$work/on" -DDUMMY_SDK=ON >"$work/on.log" 2>&1 || { cat "$work/on.log"; fail "configure"; }
grep -q "pxflow: dummy backends: on" "$work/on.log" || fail "no status line for the dummy family"
cmake --build "$work/on" --target pxflow -j"$(nproc)" >"$work/build.log" 2>&1 || { tail -30 "$work/build.log"; fail "build"; }
"$work/on/pxflow" backends | tee "$work/backends.txt"
grep -Eq '^dummy-original +available' "$work/backends.txt" || fail "dummy-original not listed as available"
"$work/on/pxflow" check --backends ref-original,dummy-original --require dummy-original --generated-only | tee "$work/check.txt"
grep -Eq '^dummy-original +passed' "$work/check.txt" || fail "dummy-original did not pass"

if cmake "${common[@]}" -B "$work/required" -DDUMMY_SDK=OFF -DPXFLOW_REQUIRE_DUMMY=ON >"$work/required.log" 2>&1; then
  fail "a required family with its SDK missing configured"
fi
tr -s " \n" " " <"$work/required.log" | grep -q "dummy backends required (PXFLOW_REQUIRE_DUMMY) but the dummy SDK is missing" || fail "no reason given"

cmake "${common[@]}" -B "$work/off" -DDUMMY_SDK=OFF >"$work/off.log" 2>&1 || fail "an optional family with its SDK missing failed the configure"
grep -q "pxflow: dummy backends: off (the dummy SDK is missing" "$work/off.log" || fail "no off line"
echo "one-call family: ok"
