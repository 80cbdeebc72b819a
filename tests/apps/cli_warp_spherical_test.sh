#!/usr/bin/env bash
# CLI tests of `stratum warp` for the spherical-polygon and tabulated warps:
# correct output on small cases with closed forms, and the
# bad-input contract of issue 3 §6 (message naming the parameter, its value
# and what is allowed; non-zero exit; no partial output file).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3

expect_error() {  # expect_error TEXT args...: non-zero exit, TEXT in stderr, nothing on stdout
  local text=$1; shift
  if "$stratum" "$@" >"$tmp/out" 2>"$tmp/err"; then fail "'$*' succeeded"; return; fi
  grep -qF -- "$text" "$tmp/err" && [ ! -s "$tmp/out" ] && ok || fail "'$*' stderr lacks '$text': $(cat "$tmp/err")"
}

# Unit directions with pdf 1/Ω: the face of the octant seen from its corner has Ω = π/2.
"$stratum" warp --map spherical-triangle -n 500 --warp-param vertices=1,0,0,0,1,0,0,0,1 --format npy -o "$tmp/t.npy" && \
$py -c "
import numpy as np; a = np.load('$tmp/t.npy'); assert a.shape == (500, 4), a.shape
assert np.allclose(np.linalg.norm(a[:, :3], axis=1), 1) and np.all(a[:, :3] >= -1e-12)
assert np.allclose(a[:, 3], 2 / np.pi)" && ok || fail "spherical-triangle octant"

# A 2 x 2 square seen from 1 above its centre: 4 asin(ab / √((a² + 4d²)(b² + 4d²))) = 4 asin(1/2) = 2π/3.
"$stratum" warp --map spherical-rectangle -n 200 --warp-param corner=-1,-1,0 --warp-param edge_u=2,0,0 --warp-param edge_v=0,2,0 \
  --warp-param origin=0,0,1 --format csv -o "$tmp/r.csv" && \
$py -c "
import numpy as np; a = np.loadtxt('$tmp/r.csv', delimiter=',', ndmin=2); assert a.shape == (200, 4), a.shape
assert np.allclose(a[:, 3], 1 / (2 * np.pi / 3)) and np.all(a[:, 2] < 0)
t = -1 / a[:, 2]; assert np.all(np.abs(a[:, 0] * t) <= 1 + 1e-12) and np.all(np.abs(a[:, 1] * t) <= 1 + 1e-12)" \
  && ok || fail "spherical-rectangle square"

# Tabulated values from a file (@FILE); zero bins are never sampled; pdf = f / mean(f).
printf '1 0\n3 0 4\n' > "$tmp/v.txt"
"$stratum" warp --map piecewise-1d -n 400 --warp-param values=@"$tmp/v.txt" --warp-param width=5 --sampler sobol > "$tmp/p.txt" && \
$py -c "
import numpy as np; a = np.loadtxt('$tmp/p.txt', ndmin=2); bins = np.floor(a[:, 0] * 5).astype(int)
assert set(bins) == {0, 2, 4}, set(bins); assert np.allclose(a[:, 1], np.array([1, 0, 3, 0, 4])[bins] / 1.6)" \
  && ok || fail "piecewise-1d from @FILE"
"$stratum" warp --map alias -n 300 --warp-param values=2,0,6 --format npy -o "$tmp/a.npy" && \
$py -c "
import numpy as np; a = np.load('$tmp/a.npy'); i = np.floor(a[:, 0] * 3).astype(int)
assert set(i) <= {0, 2} and np.allclose(a[:, 1], np.array([0.25, 0, 0.75])[i] * 3)" && ok || fail "alias"

# Bad input (issue 3 §6).
expect_error "invalid vertices = (0, 0, 1), (1, 1, 1), (2, 2, 1)" warp --map spherical-triangle -n 4 --warp-param vertices=0,0,1,1,1,1,2,2,1
expect_error "positive solid angle" warp --map spherical-triangle -n 4 --warp-param vertices=1,0,0,0,1,0,1,1,0
expect_error "each vertex must differ from the origin" warp --map spherical-triangle-projected -n 4 --warp-param vertices=0,0,0,1,0,1,0,1,1
expect_error "invalid vertices = (6 values): must be 9 finite reals" warp --map spherical-triangle -n 4 --warp-param vertices=0,0,1,1,0,1
expect_error "invalid edge_u = (0, 0, 0): must be non-zero" warp --map spherical-rectangle -n 4 --warp-param edge_u=0,0,0
expect_error "must not be parallel to edge_u" warp --map spherical-rectangle -n 4 --warp-param edge_u=1,0,0 --warp-param edge_v=3,0,0
expect_error "must be perpendicular to edge_u" warp --map spherical-rectangle-projected -n 4 --warp-param edge_v=1,1,0
expect_error "invalid origin = (0.25, 3, 1): must not lie on the rectangle's plane" warp --map spherical-rectangle -n 4 --warp-param origin=0.25,3,1
expect_error "invalid normal = (0, 0, 0): must be a non-zero vector" warp --map spherical-triangle-projected -n 4 --warp-param normal=0,0,0
expect_error "invalid values[1] = -1: must be a finite real in [0, inf)" warp --map piecewise-1d -n 4 --warp-param values=1,-1 --warp-param width=2
expect_error "invalid values = (all 3 values zero)" warp --map alias -n 4 --warp-param values=0,0,0
expect_error "invalid values[1] = nan: must be a finite real" warp --map piecewise-2d -n 4 --warp-param values=1,nan --warp-param width=2 --warp-param height=1
expect_error "invalid values = (5 values): must hold width × height = 2 × 2 = 4 values" warp --map piecewise-2d -n 4 --warp-param values=1,2,3,4,5 --warp-param width=2 --warp-param height=2
expect_error "invalid values = (3 values): must hold width = 4 values" warp --map piecewise-1d -n 4 --warp-param values=1,2,3 --warp-param width=4
expect_error "invalid width = 2.5: must be an integer in [1, 2^40]" warp --map piecewise-2d -n 4 --warp-param values=1,2 --warp-param width=2.5 --warp-param height=1
expect_error "invalid height = 0: must be an integer in [1, 2^40]" warp --map piecewise-2d -n 4 --warp-param values=1,2 --warp-param width=2 --warp-param height=0
expect_error "invalid width = -2: must be an integer in [1, 2^40]" warp --map piecewise-1d -n 4 --warp-param values=1,2 --warp-param width=-2
expect_error "invalid values = (missing)" warp --map alias -n 4
expect_error "invalid origin = (0.25, 3, 1)" warp --map spherical-rectangle -n 4 --warp-param origin=0.25,3,1 -o "$tmp/bad.npy" --format npy
[ ! -e "$tmp/bad.npy" ] && ok || fail "partial file left after bad parameter"
[ -z "$(ls -A "$tmp" | grep -v -e '^out$' -e '^err$' -e '^[trpav]\.\(npy\|csv\|txt\)$')" ] && ok || fail "stray files: $(ls -A "$tmp")"

finish
