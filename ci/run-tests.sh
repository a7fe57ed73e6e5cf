#!/usr/bin/env bash
# The whole test suite: set up, build, run every test; then the same tests built with
# AddressSanitizer + UndefinedBehaviorSanitizer (tests labelled no-sanitizer opt out, each saying
# why in its CMakeLists.txt). Exits non-zero when anything fails.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
jobs=$(nproc)

echo "== build and test (Release)"
"$root/ci/build.sh" "$root/build"
ctest --test-dir "$root/build" -j"$jobs" --output-on-failure

echo "== build and test (ASan + UBSan)"
"$root/ci/build.sh" "$root/build-sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPXFLOW_SANITIZE=ON
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$root/build-sanitize" -j"$jobs" --output-on-failure -LE no-sanitizer
