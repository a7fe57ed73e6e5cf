#!/usr/bin/env bash
# A new family's libraries are installed with no install line of their own: a build configured
# with tests/install/library_family (one pxflow_backend_family() call whose LINK is a library of
# its own, an SDK's imported target found in its folder and Threads::Threads found higher up)
# configures, exports that library, links it from pxflow::core, finds the SDK in
# pxflowConfig.cmake (by the package its folder names for the namespace) and names both in
# pxflow.pc, in link order, while its include folder and definition stay out of the export.
# Configure only.
# Usage: family_install.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1
work=$2
rm -rf "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake -S "$src" -B "$work" -DBUILD_TESTING=OFF -DPXFLOW_WITH_ALL=OFF -DPXFLOW_MAN_PAGES=OFF \
      -DPXFLOW_WITH_LIBRARY_FAMILY=ON "-DPXFLOW_EXTRA_FAMILY_DIRS=$src/tests/install/library_family" \
      >"$work.log" 2>&1 || { cat "$work.log"; fail "configure"; }
grep -q "pxflow: installed libraries: pxflow_core pxflow_library_family_kernel pxflow_own_files pxflow_interrupt pxflow_reference" \
  "$work.log" || { grep "installed libraries" "$work.log"; fail "the family's library is not installed, or not in link order"; }

targets=$(echo "$work"/CMakeFiles/Export/*/pxflowTargets.cmake)
grep -q "add_library(pxflow::library_family_kernel STATIC IMPORTED)" "$targets" \
  || fail "pxflowTargets.cmake does not export the family's library"
# The whole block first: `... | grep -q` under pipefail races with the writer (SIGPIPE).
core_block=$(grep -A4 "set_target_properties(pxflow::core PROPERTIES" "$targets")
grep "INTERFACE_LINK_LIBRARIES" <<<"$core_block" \
  | grep -F '\$<LINK_ONLY:pxflow::library_family_kernel>;\$<LINK_ONLY:FakeSdk::fake>' >/dev/null \
  || fail "pxflow::core does not link the family's library and the SDK"
grep -q "libpxflow_library_family_kernel.a" "$work/cmake_install.cmake" \
  || fail "cmake --install would not copy the family's library"
grep -qx "find_dependency(FakeSdkPackage)" "$work/pxflow-package/pxflowConfig.cmake" \
  || fail "pxflowConfig.cmake does not find the SDK"
grep -q "^Libs: .*-lpxflow_core -lpxflow_library_family_kernel -lpxflow_own_files -lpxflow_interrupt -lpxflow_reference .*-L/opt/fakesdk/lib -lfakesdk" \
  "$work/pxflow-package/pxflow.pc" || { grep Libs "$work/pxflow-package/pxflow.pc"; fail "pxflow.pc"; }
"$src/tests/install/exported_interface.sh" "$work"  # the family's folder and definition stay its own
echo "family install: ok"
