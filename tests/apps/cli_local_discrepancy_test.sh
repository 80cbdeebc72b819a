#!/usr/bin/env bash
# CLI tests of `stratum local-discrepancy` (the grid of Δ = n/N − xy and the
# box attaining D*) and of the registry measures star-box and koksma-hlawka
# through `stratum discrepancy`: values against brute force computed here in
# numpy, and the bad-input contract (message, non-zero exit, no file).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3

# 40 random points with two on grid lines (x = 0.5, y = 0.25): the counts are half-open.
$py -c "
import numpy as np
x = np.random.default_rng(3).random((40, 2)); x[0, 0] = 0.5; x[1, 1] = 0.25
np.savetxt('$tmp/p.txt', x, fmt='%.17g')"
"$stratum" local-discrepancy "$tmp/p.txt" -r 8 -o "$tmp/grid.npy" --format npy && ok || fail "grid to npy"
"$stratum" local-discrepancy "$tmp/p.txt" -r 8 >"$tmp/grid.txt" && ok || fail "grid to stdout"
"$stratum" local-discrepancy "$tmp/p.txt" --resolution 8 --format csv -o "$tmp/grid.csv" && ok || fail "grid to csv"
$py - "$tmp/p.txt" "$tmp/grid.npy" "$tmp/grid.txt" "$tmp/grid.csv" <<'PY' && ok || fail "grid equals the brute-force count"
import sys, numpy as np
p = np.loadtxt(sys.argv[1]); n = len(p); r = 8
want = np.array([[np.sum((p[:, 0] < i / r) & (p[:, 1] < j / r)) / n - (i / r) * (j / r)
                  for i in range(r + 1)] for j in range(r + 1)])
for got in (np.load(sys.argv[2]), np.loadtxt(sys.argv[3]), np.loadtxt(sys.argv[4], delimiter=",")):
    assert got.shape == (r + 1, r + 1), got.shape
    assert np.max(np.abs(got - want)) < 1e-14, np.max(np.abs(got - want))
PY

# --box: D* and its box against a brute force over the critical corners; the
# registry's star-box and star agree with it.
"$stratum" local-discrepancy "$tmp/p.txt" --box >"$tmp/box.txt" && ok || fail "--box"
"$stratum" discrepancy "$tmp/p.txt" -m star-box --json >"$tmp/box.json" && ok || fail "star-box measure"
"$stratum" discrepancy "$tmp/p.txt" -m star --json >"$tmp/star.json" && ok || fail "star measure"
$py - "$tmp/p.txt" "$tmp/box.txt" "$tmp/box.json" "$tmp/star.json" <<'PY' && ok || fail "box against brute force"
import json, sys, numpy as np
p = np.loadtxt(sys.argv[1]); n = len(p)
xs, ys = np.append(p[:, 0], 1.0), np.append(p[:, 1], 1.0)
best = 0.0
for x in xs:
    for y in ys:
        op = np.sum((p[:, 0] < x) & (p[:, 1] < y)) / n
        cl = np.sum((p[:, 0] <= x) & (p[:, 1] <= y)) / n
        best = max(best, x * y - op, cl - x * y)
box = json.load(open(sys.argv[3]))["measures"][0]
star = json.load(open(sys.argv[4]))["measures"][0]["value"]
assert abs(box["value"] - best) < 1e-15 and abs(star - best) < 1e-15, (box, star, best)
e = box["extras"]
inside = (p[:, 0] <= e["x"]) & (p[:, 1] <= e["y"]) if e["closed"] else (p[:, 0] < e["x"]) & (p[:, 1] < e["y"])
assert inside.sum() == e["count"], (inside.sum(), e)
assert abs(abs(e["count"] / n - e["x"] * e["y"]) - best) < 1e-15
assert repr(box["value"]) in open(sys.argv[2]).read(), open(sys.argv[2]).read()
PY

# Koksma–Hlawka: each error is |mean f − ∫f| computed here, each bound V_HK·D*.
"$stratum" discrepancy --sampler halton -n 200 -m koksma-hlawka --json >"$tmp/kh.json" && ok || fail "koksma-hlawka"
"$stratum" points --sampler halton -n 200 -d 2 --format csv -o "$tmp/h.csv" && ok || fail "halton points"
$py - "$tmp/h.csv" "$tmp/kh.json" <<'PY' && ok || fail "koksma-hlawka against numpy"
import json, math, sys, numpy as np
from scipy import integrate
p = np.loadtxt(sys.argv[1], delimiter=","); x, y = p[:, 0], p[:, 1]
r = json.load(open(sys.argv[2]))["measures"][0]; e = r["extras"]; e1 = math.e - 1
exp_product = integrate.dblquad(lambda b, a: math.exp(a * b), 0, 1, 0, 1, epsabs=1e-13)[0]
cases = {"xy": (x * y, 0.25, 3.0), "exp-sum": (np.exp(x + y), e1 ** 2, (e1 + math.e) ** 2 - math.e ** 2),
         "rational": (1 / ((1 + x) * (1 + y)), math.log(2) ** 2, 0.75),
         "sin-product": (np.sin(np.pi * x) * np.sin(np.pi * y), 4 / np.pi ** 2, 4.0),
         "exp-product": (np.exp(x * y), exp_product, 3 * e1)}
for name, (values, integral, variation) in cases.items():
    assert abs(e["error:" + name] - abs(values.mean() - integral)) < 1e-12, name
    assert abs(e["bound:" + name] - variation * e["star"]) < 1e-12, name
assert e["holds"] == 5 and 0 < r["value"] <= 1, r
PY

# Bad input: the argument named, non-zero exit, no file left.
expect_error "invalid resolution = 0: must be in \[1, 4096\]" local-discrepancy "$tmp/p.txt" -r 0 -o "$tmp/bad.npy"
expect_error "invalid resolution = 5000: must be in \[1, 4096\]" local-discrepancy "$tmp/p.txt" -r 5000 -o "$tmp/bad.npy"
expect_error "resolution = abc" local-discrepancy "$tmp/p.txt" -r abc -o "$tmp/bad.npy"
expect_error "invalid d = 3" local-discrepancy --sampler halton -n 16 -d 3 -o "$tmp/bad.npy"
expect_error "format" local-discrepancy "$tmp/p.txt" --format xml -o "$tmp/bad.npy"
expect_error "input" local-discrepancy -o "$tmp/bad.npy"
expect_error "output" local-discrepancy "$tmp/p.txt" -o "$tmp/no/such/dir/g.txt"
printf '# nothing\n' >"$tmp/empty.txt"; printf '0.5 0.5\n' >"$tmp/one.txt"; printf '0.5 0.5\n0.2 -0.1\n' >"$tmp/out.txt"
expect_error "invalid input = .*empty.txt: holds no points" local-discrepancy "$tmp/empty.txt" -o "$tmp/bad.npy"
expect_error "invalid n = 1" local-discrepancy "$tmp/one.txt" -o "$tmp/bad.npy"
expect_error "invalid n = 0" local-discrepancy --sampler halton -n 0 -o "$tmp/bad.npy"
expect_error "out.txt: line 2, column 2 is -0.1: coordinates must be in \[0, 1\]" local-discrepancy "$tmp/out.txt" -o "$tmp/bad.npy"
expect_error "invalid d = 1" local-discrepancy --sampler halton -n 16 -d 1 --box -o "$tmp/bad.npy"
# The box sweep is O(N^2): --box takes at most 20000 points, as the star-box measure does.
expect_error "invalid n = 20001: .*at most 20000" local-discrepancy --sampler random -n 20001 --box -o "$tmp/bad.npy"
expect_error "invalid d = 3" discrepancy --sampler halton -n 16 -d 3 -m star-box
expect_error "param" discrepancy --sampler halton -n 16 -m koksma-hlawka --measure-param x=1
# Neither the file nor a temporary beside it.
[ -z "$(ls -A "$tmp" | grep 'bad')" ] && ok || fail "a failed run left $(ls -A "$tmp" | grep 'bad')"
finish
