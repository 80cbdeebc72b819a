#!/usr/bin/env bash
# Checks that every C++ and CUDA source follows .clang-format (Debian's
# clang-format): lists the files that do not and exits 1. A generated file
# keeps its generator's layout inside `// clang-format off` (the Sobol'
# table). With --fix, formats them in place instead.
set -euo pipefail
cd "$(dirname "$0")/.."
fix=0
[ "${1-}" = --fix ] && fix=1
command -v clang-format >/dev/null || { echo "check-format: clang-format is not installed (apt-get install clang-format)" >&2; exit 2; }
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.cu' '*.cuh')
if [ "$fix" = 1 ]; then
  clang-format -i --style=file "${files[@]}"
  exit 0
fi
unformatted=()
for f in "${files[@]}"; do
  clang-format --dry-run -Werror --style=file "$f" >/dev/null 2>&1 || unformatted+=("$f")
done
if [ "${#unformatted[@]}" -gt 0 ]; then
  echo "check-format: ${#unformatted[@]} file(s) differ from .clang-format (run scripts/check-format.sh --fix):" >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files follow .clang-format"
