#!/usr/bin/env bash
# The heavy commands under `mpirun -np K` (K = 2, 3) give the output of one
# process, byte for byte (JSON: value for value, timings aside), including
# K larger than the work items; bad input gives one message and a non-zero
# exit on every rank; a failing rank stops the job with its message, no hang.
# Registered only when the CLI is built with MPI (STRATUM_MPI).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3
mpi=(mpirun --oversubscribe --mca btl self,vader)
[ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)
run() {  # run K args...: stratum on K ranks (K = 1: a plain run, no mpirun)
  local k=$1; shift
  if [ "$k" = 1 ]; then "$stratum" "$@"; else timeout 300 "${mpi[@]}" -np "$k" "$stratum" "$@"; fi
}
same_json() {  # same_json A B: equal after dropping timings (and what is derived from them)
  $py - "$1" "$2" <<'PY'
import json, sys
def strip(x):
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items()
                if not any(w in k for w in ("seconds", "efficiency", "time", "ns_per"))}
    if isinstance(x, list):
        return [strip(v) for v in x]
    return x
a, b = (strip(json.load(open(p))) for p in sys.argv[1:3])
if a != b:
    sys.exit(f"differ: {json.dumps(a)[:400]} vs {json.dumps(b)[:400]}")
PY
}
identical() {  # identical NAME args...: text output of 1, 2 and 3 ranks byte for byte
  local name=$1; shift
  run 1 "$@" >"$tmp/$name.1" 2>"$tmp/$name.err1" || { fail "$name on 1 process: $(cat "$tmp/$name.err1")"; return; }
  for k in 2 3; do
    run "$k" "$@" >"$tmp/$name.$k" 2>"$tmp/$name.err$k" || { fail "$name on $k ranks: $(tail -3 "$tmp/$name.err$k")"; continue; }
    cmp -s "$tmp/$name.1" "$tmp/$name.$k" && ok || fail "$name on $k ranks differs: $(diff "$tmp/$name.1" "$tmp/$name.$k" | head -4)"
  done
}
identical_json() {  # identical_json NAME args... (with --json)
  local name=$1; shift
  run 1 "$@" >"$tmp/$name.1" 2>"$tmp/$name.err1" || { fail "$name on 1 process: $(cat "$tmp/$name.err1")"; return; }
  for k in 2 3; do
    run "$k" "$@" >"$tmp/$name.$k" 2>"$tmp/$name.err$k" || { fail "$name on $k ranks: $(tail -3 "$tmp/$name.err$k")"; continue; }
    same_json "$tmp/$name.1" "$tmp/$name.$k" && ok || fail "$name on $k ranks"
  done
}

# --- the O(N^2) discrepancies and the star-discrepancy bounds: the same digits -------------
for m in cd wd md l2-star; do
  identical "disc-$m" discrepancy -m "$m" -s random -n 3000 -d 4 --seed 5 --json
done
identical "disc-star" discrepancy -m star -s halton -n 200 -d 3 --json
identical "disc-tiny" discrepancy -m cd -s random -n 40 -d 5 --json  # 2 row blocks: rank 2 has none

# --- runs ----------------------------------------------------------------------------------
identical_json integrate integrate --integrand genz-gaussian -d 3 -s sobol:owen -n 256 --runs 7 --json
identical_json tolerance integrate --integrand genz-gaussian -d 3 -s sobol:owen -n 16 --runs 5 --abs-tol 1e-3 --json
identical_json converge converge --integrand genz-gaussian -d 2 --samplers random,sobol:owen --n 16:256:4 --runs 5 --json
identical_json dimension study dimension --dims 1:2 --n 16:256 --runs 3 --json
identical_json importance study importance --runs 3 --samples 64 --json
identical_json mis study mis --exponents 1,100 --angles 2,30 --runs 3 --samples 64 --json
identical mis-table study mis --exponents 10 --angles 10 --runs 2 --samples 8
identical_json mitchell study mitchell --counts 16,64 --realizations 2 --lines 200 --json

# --- render: image, EXR, variance and the reference cache, byte for byte --------------------
render_args=(render --spp 4 --width 40 --height 24 --sampler sobol --quiet)  # 2 rows of tiles: rank 2 has none
for k in 1 2 3; do
  run "$k" "${render_args[@]}" -o "$tmp/r$k.png" --exr "$tmp/r$k.exr" --variance "$tmp/v$k.exr" 2>"$tmp/render.err" \
    || fail "render on $k: $(tail -3 "$tmp/render.err")"
  run "$k" render --reference --reference-spp 8 --width 40 --height 24 --cache "$tmp/cache$k" -o "$tmp/ref$k.png" --quiet \
    2>"$tmp/ref.err" || fail "render --reference on $k: $(tail -3 "$tmp/ref.err")"
done
for k in 2 3; do
  for f in "r$k.png" "r$k.exr" "v$k.exr" "ref$k.png"; do
    cmp -s "$tmp/${f/$k/1}" "$tmp/$f" && ok || fail "$f differs from one process's"
  done
  [ "$(ls "$tmp/cache$k")" = "$(ls "$tmp/cache1")" ] && [ "$(ls "$tmp/cache1" | wc -l)" = 3 ] && ok \
    || fail "reference cache on $k ranks: $(ls "$tmp/cache$k") against $(ls "$tmp/cache1")"
  for f in "$tmp"/cache1/*.exr; do  # the .json metadata beside them holds their fingerprints
    cmp -s "$f" "$tmp/cache$k/$(basename "$f")" && ok || fail "cache entry $(basename "$f") on $k ranks"
  done
done
# the cached reference is loaded by every rank alike
# One progress bar for the whole job: rank 0 alone writes a line per pass (--progress: under mpirun stderr is
# not a terminal), for a render and for a reference.
for k in 2 3; do
  run "$k" render --spp 4 --passes 4 --width 40 --height 24 --progress -o "$tmp/p$k.png" >/dev/null 2>"$tmp/p.err" \
    || fail "render --progress on $k: $(tail -3 "$tmp/p.err")"
  [ "$(grep -c 'rendering: pass' "$tmp/p.err")" = 4 ] && grep -q 'rendering: pass 4/4' "$tmp/p.err" && ok \
    || fail "render --progress on $k ranks: $(cat "$tmp/p.err")"
  run "$k" render --reference --reference-spp 8 --passes 2 --width 40 --height 24 --cache "$tmp/pcache$k" --progress \
    -o "$tmp/pr$k.png" >/dev/null 2>"$tmp/p.err" || fail "render --reference --progress on $k: $(tail -3 "$tmp/p.err")"
  [ "$(grep -c 'rendering: pass' "$tmp/p.err")" = 2 ] && ok || fail "render --reference --progress on $k ranks: $(cat "$tmp/p.err")"
done
run 2 render --reference --reference-spp 8 --width 40 --height 24 --cache "$tmp/cache1" -o "$tmp/again.png" >"$tmp/out" 2>&1 \
  && grep -q "cached" "$tmp/out" && cmp -s "$tmp/ref1.png" "$tmp/again.png" && ok || fail "cached reference on 2 ranks: $(cat "$tmp/out")"
ls -A "$tmp" | grep -q '^\.' && fail "a hidden temporary file is left: $(ls -A "$tmp")" || ok

cat >"$tmp/configs.json" <<'JSON'
[{"label": "random", "sampler": "random", "spp": 4}, {"label": "sobol", "sampler": "sobol", "spp": 4}]
JSON
identical_json compare compare --configs "$tmp/configs.json" --reference-spp 8 --width 32 --height 40 \
  --cache "$tmp/cache-compare" --json

# --- bad input: refused by every rank before any work, one message -------------------------
if run 3 discrepancy -m cd -s random -n -5 >"$tmp/out" 2>"$tmp/err"; then fail "bad n accepted on 3 ranks"
else
  [ "$(grep -c 'stratum: error' "$tmp/err")" = 1 ] && grep -q "invalid n" "$tmp/err" && ok \
    || fail "bad input on 3 ranks: want one message, got: $(cat "$tmp/err")"
fi
if run 2 report --quick -o "$tmp/report" >"$tmp/out" 2>"$tmp/err"; then fail "report accepted on 2 ranks"
else grep -q "report runs as one process" "$tmp/err" && [ ! -e "$tmp/report/index.html" ] && ok || fail "report on 2 ranks: $(cat "$tmp/err")"; fi

# --- a failing rank: the job ends with its message, exit non-zero, no hang -----------------
for rank in 0 1; do
  start=$(date +%s)
  if STRATUM_FAULT_RANK=$rank run 2 discrepancy -m cd -s random -n 3000 -d 4 >"$tmp/out" 2>"$tmp/err"; then
    fail "an injected fault on rank $rank exits 0"
  else
    [ "$(grep -c 'fault injected' "$tmp/err")" = 1 ] && [ $(($(date +%s) - start)) -lt 120 ] && ok \
      || fail "fault on rank $rank: $(cat "$tmp/err")"
  fi
  [ -s "$tmp/out" ] && fail "a failed job printed a result: $(cat "$tmp/out")" || ok
done
STRATUM_FAULT_RANK=1 run 3 render --spp 2 --width 40 --height 24 --quiet -o "$tmp/fault.png" >"$tmp/out" 2>"$tmp/err"
[ $? != 0 ] && grep -q "rank 1: fault injected" "$tmp/err" && [ ! -e "$tmp/fault.png" ] && ok \
  || fail "render with a failing rank: $(cat "$tmp/err")"
finish
