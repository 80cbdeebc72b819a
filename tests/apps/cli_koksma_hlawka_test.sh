#!/usr/bin/env bash
# CLI tests of `stratum koksma-hlawka`: every estimate, error and bound
# against numpy (closed-form integrals and variations written out here, the
# integral of e^(xy) by scipy's dblquad), D* against a brute force over the
# critical corners, and the bad-input contract (message, non-zero exit,
# nothing on stdout).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3

# Shared by the checks below: the functions with their integrals and V_HK
# (Owen 2005, eq. (12): a product g(x)h(y) has V_HK = (V(g)+|g(1)|)(V(h)+|h(1)|) - |g(1)h(1)|).
cat >"$tmp/oracle.py" <<'PY'
import math, numpy as np
from scipy import integrate
e = math.e
FUNCTIONS = {
    "xy": (lambda x, y: x * y, 0.25, 2 * 2 - 1),
    "exp-sum": (lambda x, y: np.exp(x + y), (e - 1) ** 2, (2 * e - 1) ** 2 - e ** 2),
    "rational": (lambda x, y: 1 / ((1 + x) * (1 + y)), math.log(2) ** 2, 1.0 * 1.0 - 0.25),
    "sin-product": (lambda x, y: np.sin(np.pi * x) * np.sin(np.pi * y), (2 / math.pi) ** 2, 2 * 2),
    "exp-product": (lambda x, y: np.exp(x * y),
                    integrate.dblquad(lambda b, a: math.exp(a * b), 0, 1, 0, 1, epsabs=1e-13)[0], 3 * (e - 1)),
}

def brute_star(p):
    """D* over every critical corner (point coordinates or 1), both limits."""
    n = len(p)
    xs, ys = np.append(p[:, 0], 1.0), np.append(p[:, 1], 1.0)
    best = 0.0
    for x in xs:
        lx, ex = p[:, 0] < x, p[:, 0] <= x
        op = ((p[None, :, 1] < ys[:, None]) & lx).sum(1) / n
        cl = ((p[None, :, 1] <= ys[:, None]) & ex).sum(1) / n
        best = max(best, np.max(x * ys - op), np.max(cl - x * ys))
    return best

def check(report, p, star):
    """Every row of the JSON report against numpy; returns the number that hold."""
    assert report["n"] == len(p) and abs(report["star"] - star) < 1e-15, (report["star"], star)
    names = [row["function"] for row in report["checks"]]
    assert names == list(FUNCTIONS), names
    holding = 0
    for row in report["checks"]:
        f, integral, variation = FUNCTIONS[row["function"]]
        mean = f(p[:, 0], p[:, 1]).mean()
        assert abs(row["integral"] - integral) < 1e-12 and abs(row["variation"] - variation) < 1e-12, row
        assert abs(row["estimate"] - mean) < 1e-12 and abs(row["error"] - abs(mean - integral)) < 1e-12, row
        assert abs(row["bound"] - variation * star) <= 1e-15 * variation, row
        assert row["holds"] == (abs(mean - integral) <= variation * star), row
        holding += row["holds"]
    assert report["holds"] == holding
    return holding
PY

# A sampler's points: D* exact (brute force), every function within its bound.
"$stratum" koksma-hlawka --sampler halton -n 200 --json >"$tmp/h.json" && ok || fail "koksma-hlawka --sampler"
"$stratum" points --sampler halton -n 200 -d 2 --format csv -o "$tmp/h.csv" && ok || fail "halton points"
$py - "$tmp" <<'PY' && ok || fail "sampler's report against numpy"
import json, sys, numpy as np
sys.path.insert(0, sys.argv[1]); from oracle import check, brute_star
p = np.loadtxt(sys.argv[1] + "/h.csv", delimiter=",")
r = json.load(open(sys.argv[1] + "/h.json"))
assert r["star_kind"] == "exact" and r["source"] == "sampler halton"
assert check(r, p, brute_star(p)) == 5
PY

# A file with a given D* far too small: some checks must fail, as numpy says.
$py -c "
import numpy as np
np.savetxt('$tmp/r.txt', np.random.default_rng(8).random((60, 2)), fmt='%.17g')"
"$stratum" koksma-hlawka "$tmp/r.txt" --star 1e-4 --json >"$tmp/r.json" && ok || fail "--star"
"$stratum" koksma-hlawka "$tmp/r.txt" --star 1e-4 >"$tmp/r.out" && ok || fail "--star as text"
$py - "$tmp" <<'PY' && ok || fail "given D* against numpy"
import json, sys, numpy as np
sys.path.insert(0, sys.argv[1]); from oracle import check
p = np.loadtxt(sys.argv[1] + "/r.txt")
r = json.load(open(sys.argv[1] + "/r.json"))
assert r["star_kind"] == "given"
holding = check(r, p, 1e-4)
assert holding < 5, holding
text = open(sys.argv[1] + "/r.out").read()
assert f"holds for {holding} of 5" in text and text.count(" NO\n") == 5 - holding, text
PY

# Above 2^18 points D* is Thiemard's upper bound: at least the largest |Δ| on
# a grid of corners (a lower bound on D*, counted here by a 2D histogram).
"$stratum" koksma-hlawka --sampler random -n 270000 --seed 4 --json >"$tmp/big.json" && ok || fail "n > 2^18"
"$stratum" points --sampler random -n 270000 -d 2 --seed 4 --format npy -o "$tmp/big.npy" && ok || fail "big points"
$py - "$tmp" <<'PY' && ok || fail "upper bound on D* for n > 2^18"
import json, sys, numpy as np
sys.path.insert(0, sys.argv[1]); from oracle import check
p = np.load(sys.argv[1] + "/big.npy"); r = 64
counts = np.histogram2d(p[:, 0], p[:, 1], bins=r, range=[[0, 1], [0, 1]])[0].cumsum(0).cumsum(1) / len(p)
corners = np.arange(1, r + 1) / r
grid_max = np.max(np.abs(counts - np.outer(corners, corners)))
report = json.load(open(sys.argv[1] + "/big.json"))
assert report["star_kind"] == "upper bound" and grid_max <= report["star"] <= 1, (grid_max, report["star"])
assert check(report, p, report["star"]) == 5
PY

# --list: the functions alone, with the closed forms above.
"$stratum" koksma-hlawka --list --json >"$tmp/list.json" && ok || fail "--list --json"
"$stratum" koksma-hlawka --list | grep -q "^exp-product *e^(xy)" && ok || fail "--list as text"
$py - "$tmp" <<'PY' && ok || fail "--list against the closed forms"
import json, sys
sys.path.insert(0, sys.argv[1]); from oracle import FUNCTIONS
rows = json.load(open(sys.argv[1] + "/list.json"))
assert [row["function"] for row in rows] == list(FUNCTIONS)
for row in rows:
    _, integral, variation = FUNCTIONS[row["function"]]
    assert abs(row["integral"] - integral) < 1e-12 and abs(row["variation"] - variation) < 1e-12 and row["derivation"]
PY

# Bad input: the argument named, non-zero exit, nothing printed on stdout.
printf '0.5 0.5\n' >"$tmp/one.txt"; printf '# nothing\n' >"$tmp/empty.txt"; printf '0.5 1.5\n0.1 0.2\n' >"$tmp/out.txt"
bad() { expect_error "$@"; [ ! -s "$tmp/out" ] && ok || fail "'${*:2}' printed: $(cat "$tmp/out")"; }
bad "invalid d = 3" koksma-hlawka --sampler halton -n 16 -d 3
bad "invalid star = 1.5" koksma-hlawka --sampler halton -n 16 --star 1.5
bad "invalid star = nan" koksma-hlawka --sampler halton -n 16 --star nan
bad "star" koksma-hlawka --sampler halton -n 16 --star abc
bad "invalid n = 1" koksma-hlawka "$tmp/one.txt"
bad "empty" koksma-hlawka "$tmp/empty.txt"
bad "out.txt: line 1, column 2 is 1.5: coordinates must be in \[0, 1\]" koksma-hlawka "$tmp/out.txt"
bad "input" koksma-hlawka
bad "invalid --list" koksma-hlawka --list "$tmp/one.txt"
bad "invalid --list" koksma-hlawka --list --star 0.1
bad "threads" koksma-hlawka --sampler halton -n 16 --threads -1
finish
