#!/bin/sh
# long_functions.py can fail: a 60-line function passes, a planted 61-line one is named.
# Usage: long_functions_sees_one.sh LONG_FUNCTIONS_PY
lint=${1:?usage: long_functions_sees_one.sh LONG_FUNCTIONS_PY}
d=$(mktemp -d) || exit 1
trap 'rm -rf "$d"' EXIT
body() {  # a function named $1 of $2 lines, braces included
  echo "int $1() {"
  i=2
  while [ "$i" -lt "$2" ]; do echo "  g();  // \"{\" in a comment or a string is not a brace"; i=$((i + 1)); done
  echo "}"
}
body ok 60 > "$d/ok.cpp"
python3 "$lint" --fail "$d" || { echo "a 60-line function was called too long"; exit 1; }
body too_long 61 > "$d/long.cpp"
python3 "$lint" --fail "$d" > "$d/out.txt" 2>&1
rc=$?
cat "$d/out.txt"
[ "$rc" -eq 1 ] && grep -q "long.cpp:1: too_long: 61 lines" "$d/out.txt" && ! grep -q "ok.cpp" "$d/out.txt"
