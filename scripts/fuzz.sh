#!/usr/bin/env bash
# The libFuzzer targets of fuzz/ (docs/fuzzing.md), built with clang into
# build/fuzz and run from the committed seed corpora (fuzz/corpus/TARGET)
# plus generated inputs at the JSON nesting limit and beyond.
#   scripts/fuzz.sh [SECONDS] [TARGET...]   each target for SECONDS (default 60)
#   scripts/fuzz.sh --runs N [TARGET...]    each target for N inputs (the test command: 2000)
# New inputs go to build/fuzz/corpus/TARGET (kept between timed runs), crashes to build/fuzz/crashes/;
# a crash fails the script.
set -euo pipefail
cd "$(dirname "$0")/.."
limit=(-max_total_time=60) fresh=0
if [ "${1:-}" = --runs ]; then limit=(-runs="$2") fresh=1; shift 2
elif [[ "${1:-}" =~ ^[0-9]+$ ]]; then limit=(-max_total_time="$1"); shift; fi
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(points spec obj scene configs)
clang=$(command -v clang++ || true)
[ -n "$clang" ] || { echo "fuzz: clang++ not found (Debian: apt-get install clang)" >&2; exit 1; }
cmake -S fuzz -B build/fuzz -G Ninja -DCMAKE_CXX_COMPILER="$clang" -DCMAKE_BUILD_TYPE= >/dev/null
cmake --build build/fuzz -j "$(nproc)" >/dev/null

# Inputs too large to commit: nesting at the limit (256), just past it and
# 100 000 deep, for the JSON readers; a long spec and a long OBJ line.
generated=build/fuzz/generated
rm -rf "$generated" && mkdir -p "$generated"/{scene,configs,spec,obj,points}
/usr/bin/python3 - "$generated" <<'PY'
import sys
out = sys.argv[1]
for depth in (255, 256, 257, 100000):
    for target in ("scene", "configs"):
        open(f"{out}/{target}/nested-{depth}", "w").write("[" * depth + "]" * depth)
open(f"{out}/configs/nested-objects", "w").write('{"a":' * 300 + "1" + "}" * 300)
open(f"{out}/scene/long-string", "w").write('{"materials": {"' + "m" * 100000 + '": {}}, "shapes": []}')
open(f"{out}/spec/long", "w").write("sobol(" + ",".join(f"k{i}={i}" for i in range(2000)) + "):owen")
open(f"{out}/obj/long-face", "w").write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf" + " 1 2 3" * 2000 + "\n")
open(f"{out}/points/wide.txt", "w").write("0" + " ".join(["0.5"] * 5000) + "\n")
PY

mkdir -p build/fuzz/crashes
status=0
for target in "${targets[@]}"; do
  [ "$fresh" = 0 ] || rm -rf "build/fuzz/corpus/$target"  # a fixed number of runs starts from the seeds alone
  mkdir -p "build/fuzz/corpus/$target"
  echo "== fuzz_$target ${limit[*]}"
  # The first folder takes the new inputs; the committed corpus is only read.
  if ! build/fuzz/fuzz_"$target" "${limit[@]}" -max_len=1048576 -timeout=10 -rss_limit_mb=2048 -print_final_stats=0 \
      -artifact_prefix="build/fuzz/crashes/$target-" "build/fuzz/corpus/$target" "fuzz/corpus/$target" \
      "$generated/$target" >"build/fuzz/$target.log" 2>&1; then
    echo "fuzz_$target FAILED:"; tail -40 "build/fuzz/$target.log"; status=1
  else
    grep -E "^#[0-9]+ +DONE|Done [0-9]+ runs" "build/fuzz/$target.log" | tail -1
  fi
done
exit $status
