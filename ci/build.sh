#!/usr/bin/env bash
# Configures and builds pxflow into a build directory. Usage: ci/build.sh [BUILD_DIR [CMAKE_ARGS...]]
# Installs the Debian packages of ci/packages.txt first when any is missing.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-"$root/build"}
shift || true
"$root/ci/install-deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build" -j"$(nproc)"
