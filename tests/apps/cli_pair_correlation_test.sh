#!/usr/bin/env bash
# CLI tests of `stratum pair-correlation`: g(r) of white noise is 1 within
# its sampling error, blue noise has g = 0 inside its Poisson radius, the
# CLI gives the numbers of the Python face (stratum.pair_correlation) for the
# same file, the table and JSON forms agree, and the bad-input contract.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3
pkg="$(dirname "$stratum")/../python"

# White noise: 20 radii, N = 4096; each g(r) is an average over ~N·2πrσ·N
# pairs, so |g − 1| < 0.1 at every radius is > 5 standard errors wide.
"$stratum" pair-correlation -s random -n 4096 --seed 3 --count 20 --json >"$tmp/white.json" && ok || fail "white noise"
$py - "$tmp/white.json" <<'PY' && ok || fail "white noise g = 1"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["n"] == 4096 and d["d"] == 2 and len(d["r"]) == 20 == len(d["g"])
bad = [(r, g) for r, g in zip(d["r"], d["g"]) if abs(g - 1) > 0.1]
assert not bad, bad
PY

# Periodic Poisson disk: no pair closer than its radius, so g = 0 below it.
"$stratum" pair-correlation -s "poisson-disk(periodic=1)" -n 1024 --radii 0.004,0.008 --sigma 0.001 >"$tmp/blue.txt" && ok || fail "blue noise"
[ "$(awk '$2 != 0' "$tmp/blue.txt" | wc -l)" = 0 ] && ok || fail "poisson-disk g is not 0 inside its radius: $(cat "$tmp/blue.txt")"

# The same file through the CLI (table and JSON) and through Python.
"$stratum" points -s sobol:owen -n 512 --seed 4 -o "$tmp/p.txt" && ok || fail "points file"
"$stratum" pair-correlation "$tmp/p.txt" --radii 0.01,0.02,0.05 --sigma 0.004 -o "$tmp/g.csv" && ok || fail "table to csv"
"$stratum" pair-correlation "$tmp/p.txt" --radii 0.01,0.02,0.05 --sigma 0.004 --json >"$tmp/g.json" && ok || fail "json of the file"
if [ -d "$(dirname "$stratum")/../python/stratum" ]; then
PYTHONPATH="$pkg" $py - "$tmp/p.txt" "$tmp/g.csv" "$tmp/g.json" <<'PY' && ok || fail "CLI = Python"
import json, sys
import numpy as np
import stratum
x = np.loadtxt(sys.argv[1])
ours = stratum.pair_correlation(x, radii=[0.01, 0.02, 0.05], sigma=0.004)
table = np.loadtxt(sys.argv[2], delimiter=",")
doc = json.load(open(sys.argv[3]))
assert np.array_equal(table[:, 0], ours["r"]) and np.array_equal(table[:, 1], ours["g"]), (table, ours)
assert doc["g"] == ours["g"].tolist() and doc["sigma"] == 0.004
PY
else
  echo "skipped: this build has no Python package (the asan preset), so CLI = Python is checked in the release run"
fi

expect_error "invalid sigma = -1" pair-correlation -s random -n 10 --sigma -1
expect_error "invalid count = 0" pair-correlation -s random -n 10 --count 0
expect_error "r + 4 sigma must be at most 1/2" pair-correlation -s random -n 100 --radii 0.4 --sigma 0.1
expect_error "invalid d = 9" pair-correlation -s random -n 10 -d 9
expect_error "give either a point FILE or --sampler" pair-correlation
expect_error "invalid output" pair-correlation -s random -n 10 --json -o "$tmp/x.txt"
[ ! -e "$tmp/x.txt" ] && ok || fail "--json with -o left a file"
expect_error "invalid radius" pair-correlation -s random -n 10 --radii 0,0.1 --sigma 0.01
finish
