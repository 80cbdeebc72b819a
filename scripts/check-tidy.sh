#!/usr/bin/env bash
# Lints the header-only core (include/stratum/{sequences,patterns,
# randomizers,warps,estimators,spacetime,util,pixel}) with .clang-tidy (Debian's
# clang-tidy): one translation unit includes every core header, so each is
# parsed once (seconds, not minutes); exits 1 on any finding.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-tidy >/dev/null || { echo "check-tidy: clang-tidy is not installed (apt-get install clang-tidy)" >&2; exit 2; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
headers=(include/stratum/{sequences,patterns,randomizers,warps,estimators,spacetime,util,pixel}/*.hpp)
for header in "${headers[@]}"; do echo "#include \"${header#include/}\""; done >"$scratch/core.cpp"
status=0
clang-tidy --quiet --config-file=.clang-tidy "$scratch/core.cpp" -- -x c++ -std=c++20 -I"$PWD/include" \
  >"$scratch/findings" 2>"$scratch/log" || status=$?
if [ "$status" -ne 0 ] || grep -q . "$scratch/findings"; then
  echo "check-tidy: findings (.clang-tidy; exit $status):" >&2
  cat "$scratch/findings" >&2
  grep -v "warnings generated\|^Suppressed\|^Use -header-filter\|treated as error" "$scratch/log" >&2 || true
  exit 1
fi
echo "check-tidy: ${#headers[@]} core headers pass .clang-tidy"
