#!/usr/bin/env bash
# What an installed consumer of pxflow is given by pxflowTargets.cmake: only the installed
# include/ folder (headers as <pxflow/...>) and no compile definition. A family's include
# folders and definitions (CL_TARGET_OPENCL_VERSION, a folder holding its device_select.hpp)
# are its own target's, private (cmake/PxflowBackendFamily.cmake); this fails when one leaks.
# Usage: exported_interface.sh BUILD_DIR (the export cmake --install copies, generated at
# configure time)
set -euo pipefail
targets=$(echo "$1"/CMakeFiles/Export/*/pxflowTargets.cmake)
[[ -f $targets ]] || { echo "FAIL: no pxflowTargets.cmake in $1" >&2; exit 1; }
status=0
if grep -n "INTERFACE_COMPILE_DEFINITIONS" "$targets"; then
  echo "FAIL: $targets gives consumers compile definitions (above)" >&2
  status=1
fi
# Every include folder of every exported target, one a line.
folders=$(sed -n 's/^ *INTERFACE_INCLUDE_DIRECTORIES "\(.*\)"$/\1/p' "$targets" | tr ';' '\n')
[[ -n $folders ]] || { echo "FAIL: no INTERFACE_INCLUDE_DIRECTORIES in $targets" >&2; exit 1; }
# shellcheck disable=SC2016  # the literal text CMake writes
if grep -vxF '${_IMPORT_PREFIX}/include' <<<"$folders"; then
  echo "FAIL: $targets gives consumers include folders other than <prefix>/include (above)" >&2
  status=1
fi
[[ $status == 0 ]] && echo "exported interface: include/ only, no definitions"
exit "$status"
