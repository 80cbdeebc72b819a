#!/usr/bin/env bash
# The memory guard (docs/outputs.md): a request just above STRATUM_MEMORY_LIMIT
# is refused before any work (exit 3, the size needed and what is available,
# no output), one just under it runs.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"

limited() {  # limited BYTES ARGS...: stratum under a limit, stderr in $tmp/err
  local bytes=$1; shift
  STRATUM_MEMORY_LIMIT=$bytes "$stratum" "$@" >"$tmp/out" 2>"$tmp/err"
}
refused() {  # refused MESSAGE BYTES ARGS...
  local message=$1; shift
  limited "$@"
  local status=$?
  [ "$status" = 3 ] && grep -qF "$message" "$tmp/err" && ok || fail "'${*:2}' under $1: exit $status: $(cat "$tmp/err")"
}

# points: n x d doubles (1000 x 8 = 64000 bytes)
refused "needs 62.5 KiB for 1000 x 8 points of random, 62.5 KiB available" 63999 points -s random -n 1000 -d 8 -o "$tmp/p.txt"
[ ! -e "$tmp/p.txt" ] && ok || fail "a refused points command left its output"
limited 64000 points -s random -n 1000 -d 8 -o "$tmp/p.txt" && [ -s "$tmp/p.txt" ] && ok || fail "points under the limit: $(cat "$tmp/err")"

# discrepancy of generated points: the points (80000 bytes) and the fast
# L2-star's sort keys and column (240000 bytes), before they are generated
refused "needs 312.5 KiB for 10000 x 1 points and their l2-star measure, 312.5 KiB available" 319999 \
  discrepancy -m l2-star -s random -n 10000 -d 1
limited 320000 discrepancy -m l2-star -s random -n 10000 -d 1 && grep -q "^l2-star" "$tmp/out" && ok ||
  fail "discrepancy under the limit: $(cat "$tmp/err")"

# random-edge keeps one value per line: 2^32 lines are 32 GiB, refused before
# the points are generated, and for points from a file before the lines are drawn
refused "needs 32.0 GiB for 16 x 2 points and their edge-random measure" 1073741824 \
  discrepancy -m edge-random -s random -n 16 --measure-param lines=4294967296
"$stratum" points -s random -n 16 -o "$tmp/square.txt" || fail "points for the file case"
refused "needs 32.0 GiB for the edge-random measure of 16 x 2 points" 1073741824 \
  discrepancy "$tmp/square.txt" -m edge-random --measure-param lines=4294967296
limited 1073741824 discrepancy "$tmp/square.txt" -m edge-random --measure-param lines=1000 &&
  grep -q "^edge-random" "$tmp/out" && ok || fail "edge-random under the limit: $(cat "$tmp/err")"

# converge: 2 runs at once of 4096 x 4 points and their values (2 x 4096 x 5 x 8 = 327680 bytes)
refused "needs 320.0 KiB for 2 runs at once of 4096 x 4 points and their integrand values" 327679 \
  converge --integrand genz-gaussian -d 4 --samplers random --n 64:4096:4 --runs 4 --threads 2
limited 327680 converge --integrand genz-gaussian -d 4 --samplers random --n 64:4096:4 --runs 4 --threads 2 && ok ||
  fail "converge under the limit: $(cat "$tmp/err")"

# study dimension: 2 Sobol' runs at once of up to 729 x 2 points (23328 bytes)
refused "needs 22.8 KiB for 2 Sobol' runs at once of up to 729 x 2 points, 22.8 KiB available" 23327 \
  study dimension --dims 1:2 --n 16:1024 --threads 2
limited 23328 study dimension --dims 1:2 --n 16:1024 --threads 2 && ok || fail "study dimension under the limit: $(cat "$tmp/err")"

if has_render; then
  # render: 96 bytes per pixel (64 x 64 = 393216 bytes)
  refused "needs 384.0 KiB for a 64x64 render (its sums, mean and variance per pixel)" 393215 \
    render --width 64 --height 64 --spp 1 -q -o "$tmp/r.png"
  [ -z "$(ls -A "$tmp" | grep 'r\.png')" ] && ok || fail "a refused render left $(ls -A "$tmp")"
  limited 393216 render --width 64 --height 64 --spp 1 -q -o "$tmp/r.png" && [ -s "$tmp/r.png" ] && ok ||
    fail "render under the limit: $(cat "$tmp/err")"
  # the documented largest image needs 24 GiB: refused where there is less
  refused "needs 24.0 GiB for a 16384x16384 render" 1073741824 render --width 16384 --height 16384 -q -o "$tmp/big.png"
fi
finish
