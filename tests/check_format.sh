#!/usr/bin/env bash
# Checks that every C++ source under src/ and tests/ is as clang-format leaves it. Exit 77 (skipped) without
# clang-format.
set -uo pipefail
root=$1
format=${2:-}
if [ -z "$format" ] || [ ! -x "$format" ]; then
  echo "clang-format not found: style not checked"
  exit 77
fi
cd "$root" || exit 1
drifted=()
while IFS= read -r -d '' file; do
  "$format" --dry-run -Werror "$file" >/dev/null 2>&1 || drifted+=("$file")
done < <(find src tests \( -name '*.cpp' -o -name '*.h' \) -print0 | sort -z)
if [ ${#drifted[@]} -gt 0 ]; then
  echo "not formatted by .clang-format (fix: clang-format -i FILE):"
  printf '  %s\n' "${drifted[@]}"
  exit 1
fi
echo "all sources follow .clang-format"
