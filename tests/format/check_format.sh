#!/usr/bin/env bash
# Every C, C++, OpenCL C and GLSL file of the tree is clang-format clean (the repository's
# .clang-format; clang-format from ci/packages.txt). Prints the files that are not, with the fix.
# Usage: check_format.sh SOURCE_DIR
set -euo pipefail
cd "$1"
command -v clang-format >/dev/null || { echo "clang-format not found (bash ci/install-deps.sh installs it)"; exit 1; }
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files -co --exclude-standard '*.c' '*.h' '*.cpp' '*.hpp' '*.cl' '*.comp')
else
  mapfile -t files < <(find . -path ./build -prune -o -path './build-*' -prune -o -type f \
    \( -name '*.c' -o -name '*.h' -o -name '*.cpp' -o -name '*.hpp' -o -name '*.cl' -o -name '*.comp' \) -print)
fi
[ ${#files[@]} -gt 0 ] || { echo "no source files found under $1"; exit 1; }
bad=()
for f in "${files[@]}"; do
  [ -f "$f" ] || continue
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if [ ${#bad[@]} -gt 0 ]; then
  printf 'not clang-format clean (fix: clang-format -i FILE):\n'
  printf '  %s\n' "${bad[@]}"
  exit 1
fi
echo "clang-format clean: ${#files[@]} files"
