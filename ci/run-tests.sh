#!/usr/bin/env bash
# The whole test suite in two stages: set up, build and run every test (Release); then the same
# tests built with AddressSanitizer + UndefinedBehaviorSanitizer (tests labelled no-sanitizer are
# left out, each saying why beside its label). Both stages run even when the first fails; the
# script ends with one line per stage (passed, failed, skipped with each skip's reason, left out,
# time) and exits non-zero when anything failed.
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
jobs=$(nproc)
summary=()
status=0

# stage NAME BUILD_DIR CTEST_ARGS WHY [CMAKE_ARGS...]: build, then run the tests CTEST_ARGS
# select; WHY says why the others are left out.
stage() {
  local name=$1 build=$2 ctest_args=$3 why=$4
  shift 4
  local t0 t1 t2 registered  # `built` (1: the build succeeded) is read after the call
  t0=$(date +%s)
  echo "== $name: build ($build)"
  built=0
  if ! "$root/ci/build.sh" "$build" "$@"; then
    summary+=("$name: the build failed, no test ran, $(($(date +%s) - t0)) s")
    status=1
    return
  fi
  built=1
  t1=$(date +%s)
  echo "== $name: test"
  rm -f "$build/ctest-junit.xml"
  # --timeout: the hang guard of every test that sets none of its own (never a speed bound).
  # shellcheck disable=SC2086  # CTEST_ARGS is a list of options
  ctest --test-dir "$build" -j"$jobs" --output-on-failure --timeout 1500 \
    --output-junit "$build/ctest-junit.xml" $ctest_args || status=1
  t2=$(date +%s)
  registered=$(ctest --test-dir "$build" -N | sed -n 's/^Total Tests: //p')
  summary+=("$(python3 "$root/ci/test-summary.py" "$name" "$build/ctest-junit.xml" \
    "$((t2 - t0)) s (build $((t1 - t0)) s, tests $((t2 - t1)) s)" "${registered:-0}" \
    "$why")")
}

stage "Release" "$root/build" "" "none"
# The cross-compiled outputs (GAP8 ELFs, Cortex-M4 firmware, the AArch64 NEON check) are the
# same in both builds: the sanitizer stage copies the Release stage's when that built
# (PXFLOW_CROSS_FROM, cmake/PxflowBuildFlags.cmake), and compiles its own when it did not.
cross_from=""
[ "$built" = 1 ] && cross_from=$root/build
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# -O1 -g1 (ASan's advice: line tables name every frame of a report) compiles in half the time of
# -O2 -g (docs/test-suite.md, "The test suite's time").
stage "ASan+UBSan" "$root/build-sanitize" "-LE no-sanitizer" "label no-sanitizer" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPXFLOW_SANITIZE=ON -DPXFLOW_WERROR=OFF "-DPXFLOW_CROSS_FROM=$cross_from" \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"

echo "== summary"
printf '%s\n' "${summary[@]}"
exit "$status"
