#!/usr/bin/env bash
# Strong scaling of the distributed commands (docs/distributed.md): the same
# job on 1 process and on K MPI ranks, 1 thread each; prints the median
# seconds of REPEATS runs of each (default 3, alternating) and the
# speedup against the one-process run of the same build (that the outputs
# are identical is the test tests/apps/mpi_runs.sh).
# ONLY=TEXT keeps the rows whose job names contain TEXT (e.g. ONLY=render).
#   [REPEATS=3] [ONLY=TEXT] bash bench/mpi_scaling.sh build/release/bin/stratum [K=2]
set -euo pipefail
stratum=$1 k=${2:-2} repeats=${REPEATS:-3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mpi=(mpirun --oversubscribe --mca btl self,vader -np "$k")
[ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)
seconds() {  # seconds OUTPUT command...: wall time of one run
  local out=$1; shift
  local start end
  start=$(date +%s.%N)
  "$@" >"$out"
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { print b - a }'
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
row() {  # row NAME args...: the median of REPEATS runs of each, alternating one process and K ranks
  local name=$1; shift
  [[ "$name" == *"${ONLY:-}"* ]] || return 0
  local ones=() manys=() one many r
  for ((r = 0; r < repeats; ++r)); do  # @CACHE@: a fresh folder per run (a render's reference is not reused)
    ones+=("$(seconds "$tmp/one" "$stratum" "${@//@CACHE@/$tmp/cache-one-$r}")")
    manys+=("$(seconds "$tmp/many" "${mpi[@]}" "$stratum" "${@//@CACHE@/$tmp/cache-many-$r}")")
  done
  one=$(printf "%s\n" "${ones[@]}" | median)
  many=$(printf "%s\n" "${manys[@]}" | median)
  printf "| %s | %.2f | %.2f | %.2fx |\n" "$name" "$one" "$many" "$(awk -v a="$one" -v b="$many" 'BEGIN { print a / b }')"
}
echo "| job | 1 process (s) | $k ranks (s) | speedup |"
echo "|---|---|---|---|"
row "discrepancy -m cd, N = 120000, d = 6" discrepancy -m cd -s random -n 120000 -d 6 --threads 1 --json
row "discrepancy -m cd, N = 240000, d = 6" discrepancy -m cd -s random -n 240000 -d 6 --threads 1 --json
row "discrepancy -m wd, N = 120000, d = 6" discrepancy -m wd -s random -n 120000 -d 6 --threads 1 --json
row "render --reference, Cornell box 256x256, 128 spp" render --reference --reference-spp 128 --width 256 --height 256 \
  --threads 1 --quiet --cache @CACHE@ -o "$tmp/ref.png"
row "render --reference, Cornell box 256x256, 256 spp" render --reference --reference-spp 256 --width 256 --height 256 \
  --threads 1 --quiet --cache @CACHE@ -o "$tmp/ref.png"
row "converge, 2 samplers x 6 N x 64 runs" converge --integrand genz-gaussian -d 4 --samplers random,sobol:owen \
  --n 64:65536:4 --runs 64 --threads 1 --json
