#!/usr/bin/env bash
# Strong scaling of the distributed commands (docs/distributed.md): the same
# job on 1 process and on K MPI ranks, 1 thread each; prints seconds and the
# speedup against the one-process run of the same build (that the outputs
# are identical is the test tests/apps/mpi_runs.sh).
#   bash bench/mpi_scaling.sh build/release/bin/stratum [K=2]
set -euo pipefail
stratum=$1 k=${2:-2}
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
row() {  # row NAME args...
  local name=$1; shift
  local one many
  one=$(seconds "$tmp/one" "$stratum" "$@")
  many=$(seconds "$tmp/many" "${mpi[@]}" "$stratum" "$@")
  printf "| %s | %.2f | %.2f | %.2fx |\n" "$name" "$one" "$many" "$(awk -v a="$one" -v b="$many" 'BEGIN { print a / b }')"
}
echo "| job | 1 process (s) | $k ranks (s) | speedup |"
echo "|---|---|---|---|"
row "discrepancy -m cd, N = 120000, d = 6" discrepancy -m cd -s random -n 120000 -d 6 --threads 1 --json
row "discrepancy -m wd, N = 120000, d = 6" discrepancy -m wd -s random -n 120000 -d 6 --threads 1 --json
# a fresh cache folder per run, so that each renders the reference
one=$(seconds "$tmp/one" "$stratum" render --reference --reference-spp 128 --width 256 --height 256 --threads 1 --quiet \
  --cache "$tmp/cache1" -o "$tmp/ref1.png")
many=$(seconds "$tmp/many" "${mpi[@]}" "$stratum" render --reference --reference-spp 128 --width 256 --height 256 \
  --threads 1 --quiet --cache "$tmp/cache2" -o "$tmp/ref2.png")
printf "| %s | %.2f | %.2f | %.2fx |\n" "render --reference, Cornell box 256x256, 128 spp" "$one" "$many" "$(awk -v a="$one" -v b="$many" 'BEGIN { print a / b }')"
row "converge, 2 samplers x 6 N x 64 runs" converge --integrand genz-gaussian -d 4 --samplers random,sobol:owen \
  --n 64:65536:4 --runs 64 --threads 1 --json
