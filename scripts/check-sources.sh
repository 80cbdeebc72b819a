#!/usr/bin/env bash
# The CMake files list their sources by name (no GLOB): checks that every
# source, test, benchmark and script in the repository is in its list, so a
# file added but not listed fails here instead of being silently left out of
# the build or the tests. (A listed file that does not exist fails CMake.)
set -euo pipefail
cd "$(dirname "$0")/.."
missing=0
check() {  # check CMAKEFILE DIRECTORY PATTERN...: every tracked DIRECTORY file matching a PATTERN is named in CMAKEFILE
  local cmakefile=$1 directory=$2; shift 2
  local base; base=$(dirname "$cmakefile")
  local file pattern
  for pattern in "$@"; do
    while read -r file; do
      [ -n "$file" ] || continue
      local named=${file#"$base"/}
      [ "$base" = . ] && named=$file
      grep -qF -- "$named" "$cmakefile" || { echo "check-sources: $file is not listed in $cmakefile" >&2; missing=1; }
    done < <(git ls-files -- "$directory/$pattern" | grep -v "^$directory/.*/" || true)
  done
}
for area in registry io analysis render report; do check CMakeLists.txt "src/$area" '*.cpp'; done
check CMakeLists.txt src/plot/scripts '*.py'
check CMakeLists.txt apps/stratum '*.cpp'
check python/CMakeLists.txt python/src '*.cpp'
check python/CMakeLists.txt python/stratum '*.py'
check bench/CMakeLists.txt bench '*_bench.cpp'
check tests/CMakeLists.txt tests/apps '*_test.sh'
while read -r file; do  # the gtests, in every folder of tests/
  grep -qF -- "${file#tests/}" tests/CMakeLists.txt || { echo "check-sources: $file is not listed in tests/CMakeLists.txt" >&2; missing=1; }
done < <(git ls-files -- 'tests/*_test.cpp')
# The core's include tree holds the header-only core alone (DESIGN.md: "nothing in core reads up"):
# a library's headers live in src/<library>/include, so no program that uses
# only stratum::core sees them on its include path.
while read -r file; do
  echo "check-sources: $file is in the core's include tree but not in a core folder (sequences, patterns, pixel," \
    "randomizers, warps, estimators, spacetime, util): a library header goes to src/<library>/include" >&2
  missing=1
done < <(git ls-files -- include | grep -vE '^include/stratum/(sequences|patterns|randomizers|warps|estimators|spacetime|util|pixel)/[^/]+\.hpp$' || true)
[ "$missing" = 0 ] && echo "check-sources: every source is listed in its CMake file"
exit "$missing"
