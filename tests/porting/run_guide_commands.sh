#!/bin/bash
# Runs every ```sh block of a guide (docs/PORTING.md) against one build, so the guide cannot rot.
# Usage: run_guide_commands.sh GUIDE SOURCE_DIR BUILD_DIR
#
# Each block runs with bash -euo pipefail in a scratch folder that looks like a checkout whose
# build is in build/ (symlinks to the source tree's top-level entries, build -> BUILD_DIR), so the
# guide's commands are written exactly as an engineer types them at the repository root and
# their outputs (out/...) land in the scratch folder. A block whose first line is
# `# needs backend: NAME` is skipped, with the reason, when `build/pxflow backends` says NAME
# cannot run here. Exit 0 when every block ran and passed, 1 when one failed, 77 (skip) when
# none failed but some were skipped.
set -uo pipefail
guide=$1 source_dir=$2 build_dir=$3
[[ -f $guide ]] || { echo "$guide: no such file"; exit 1; }

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for entry in "$source_dir"/*; do
  name=$(basename "$entry")
  [[ $name == build* || $name == out ]] && continue
  ln -s "$entry" "$scratch/$name"
done
ln -s "$build_dir" "$scratch/build"

# Split the guide into blocks: block_N.sh holds the commands, block_N.line the guide line.
awk -v dir="$scratch" '
  /^```sh[[:space:]]*$/ { n++; inside = 1; print NR + 1 > (dir "/block_" n ".line"); next }
  /^```/ && inside { inside = 0; next }
  inside { print > (dir "/block_" n ".sh") }
' "$guide"

passed=0 failed=0 skipped=0
for script in $(ls "$scratch"/block_*.sh 2>/dev/null | sort -V); do
  line=$(cat "${script%.sh}.line")
  where="$(basename "$guide"):$line"
  needs=$(sed -n '1s/^# needs backend: *\([A-Za-z0-9_-]*\).*/\1/p' "$script")
  if [[ -n $needs ]]; then
    status=$(cd "$scratch" && build/pxflow backends | awk -v n="$needs" '$1 == n { print $2 }')
    if [[ $status != available ]]; then
      echo "skip $where (backend $needs is ${status:-not compiled in} here)"
      skipped=$((skipped + 1))
      continue
    fi
  fi
  start=$(date +%s%N)
  output=$(cd "$scratch" && timeout 300 bash -euo pipefail "$script" 2>&1)
  rc=$?
  ms=$((($(date +%s%N) - start) / 1000000))
  if [[ $rc -eq 0 ]]; then
    echo "ok   $where (${ms} ms)"
    passed=$((passed + 1))
  else
    echo "FAIL $where exit $rc; the block was:"
    sed 's/^/    /' "$script"
    echo "  its output (last 20 lines):"
    echo "$output" | tail -20 | sed 's/^/    /'
    failed=$((failed + 1))
  fi
done
echo "$passed passed, $failed failed, $skipped skipped ($(basename "$guide"))"
if [[ $((passed + failed + skipped)) -eq 0 ]]; then
  echo "no \`\`\`sh block found in $guide"
  exit 1
fi
[[ $failed -gt 0 ]] && exit 1
[[ $skipped -gt 0 ]] && exit 77
exit 0
