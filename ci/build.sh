#!/usr/bin/env bash
# Configures and builds pxflow into a build directory. Usage: ci/build.sh [BUILD_DIR [CMAKE_ARGS...]]
# Installs the Debian packages of ci/packages.txt first when any is missing.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-"$root/build"}
shift || true
"$root/ci/install-deps.sh"
# CI and the README commands require every backend family this machine kind has: a missing SDK
# fails the configure instead of silently dropping a family. A warning fails the build
# (PXFLOW_WERROR) unless the caller turns it off: the sanitizer stage of ci/run-tests.sh does,
# because GCC's flow warnings are not reliable under the sanitizers' instrumentation.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPXFLOW_REQUIRE_ALL=ON -DPXFLOW_WERROR=ON \
  "$@" >/dev/null
# PXFLOW_BUILD_TARGET: build only that target (the main job needs only the CLI, not the tests).
cmake --build "$build" -j"$(nproc)" ${PXFLOW_BUILD_TARGET:+--target "$PXFLOW_BUILD_TARGET"}
