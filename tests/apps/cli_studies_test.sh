#!/usr/bin/env bash
# CLI tests of `stratum study dimension` and `stratum study importance`:
# tables, JSON checked against theory (midpoint slope −2/d, σ/√N, E = πL for
# the sky, zero variance for cosine sampling of the sky), determinism across
# thread counts, figures, and the bad-input contract (message naming the
# argument, non-zero exit, no partial output file).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3

# --- the program and `study` themselves --------------------------------------
# --version prints CMake's project version and exits 0.
version=$(sed -n 's/^project(stratum VERSION \([0-9.]*\).*/\1/p' "$(dirname "${BASH_SOURCE[0]}")/../../CMakeLists.txt")
[ -n "$version" ] && [ "$("$stratum" --version)" = "stratum $version" ] && ok || fail "--version prints stratum $version"
# study --help lists the studies, and the top-level help names them instead of pointing to study --help.
"$stratum" study --help >"$tmp/help" && ok || fail "study --help"
for name in mitchell dimension importance mis; do grep -q "^  $name " "$tmp/help" && ok || fail "study --help lists $name"; done
"$stratum" --help | grep '^  study ' >"$tmp/help"
grep -q 'mitchell, dimension, importance or mis' "$tmp/help" && ! grep -q 'study --help' "$tmp/help" && ok \
  || fail "--help describes study: $(cat "$tmp/help")"
rm -f "$tmp/help"

# --- dimension ---------------------------------------------------------------
"$stratum" study dimension --dims 1:3 --n 16:1024 --runs 4 >"$tmp/table" && ok || fail "dimension table"
grep -q '^d = 3: exact 1' "$tmp/table" && ok || fail "table lacks d = 3: $(head -5 "$tmp/table")"

"$stratum" study dimension --dims 1:4 --n 16:65536 --runs 8 --json >"$tmp/d.json" && ok || fail "dimension --json"
$py - "$tmp/d.json" <<'EOF' && ok || fail "dimension JSON contents"
import json, math, sys
data = json.load(open(sys.argv[1]))
assert data["rule"] == "midpoint" and data["integrand"] == "sine-product" and data["runs"] == 8
s = data["series"]
assert [x["d"] for x in s] == [1, 2, 3, 4], [x["d"] for x in s]
assert s[0]["n"][0] == 16 and s[0]["n"][-1] == 65536, s[0]["n"]
for x in s:
    assert all(n == m ** x["d"] for n, m in zip(x["n"], x["m"]))
    # midpoint sums of the sine product in closed form: (pi / (2m sin(pi/(2m))))^d - 1
    for m, e in zip(x["m"], x["product_error"]):
        exact = (math.pi / (2 * m * math.sin(math.pi / (2 * m)))) ** x["d"] - 1
        assert abs(e - exact) <= 1e-12 + 1e-9 * exact, (x["d"], m, e, exact)
    assert abs(x["product_slope"] - x["product_predicted_slope"]) < 0.06, x
    assert abs(x["mc_predicted"][0] - math.sqrt(((math.pi ** 2 / 8) ** x["d"] - 1) / x["n"][0])) < 1e-12
    assert len(x["sobol_rmse"]) == len(x["n"])
EOF

a=$("$stratum" study dimension --dims 2:3 --n 16:4096 --runs 4 --threads 1 --json | md5sum)
b=$("$stratum" study dimension --dims 2:3 --n 16:4096 --runs 4 --threads 2 --json | md5sum)
[ "$a" = "$b" ] && ok || fail "threads change the dimension study"
"$stratum" study dimension --dims 2 --n 16:4096 --runs 2 --rule gauss --integrand genz-gaussian --no-sobol --json \
  | $py -c 'import json,sys; s=json.load(sys.stdin)["series"]; assert len(s)==1 and s[0]["sobol_rmse"]==[] and s[0]["product_error"][-1] < 1e-12, s' \
  && ok || fail "gauss rule on genz-gaussian"

"$stratum" study dimension --dims 1:3 --n 16:256 --runs 2 --plot "$tmp/d.png" >/dev/null && ok || fail "dimension --plot"
[ "$(head -c 4 "$tmp/d.png" | od -An -c | tr -d ' ')" = '211PNG' ] && ok || fail "dimension plot is not a PNG"

expect_error "invalid runs = 0" study dimension --runs 0
expect_error "invalid runs = -3" study dimension --runs -3
expect_error "invalid runs = 1" study dimension --runs 1
expect_error "invalid dims = 5:2" study dimension --dims 5:2
expect_error "invalid dims = 0:3" study dimension --dims 0:3
expect_error "invalid dims = a:b" study dimension --dims a:b
expect_error "invalid dims = 1:65" study dimension --dims 1:65
expect_error "invalid n = 100:10" study dimension --n 100:10
expect_error "invalid n = 16:" study dimension --n 16:
expect_error "d = 9 has none" study dimension --dims 1:10 --n 16:500
expect_error "invalid rule = simpson" study dimension --rule simpson
expect_error "invalid integrand = nosuch" study dimension --integrand nosuch
expect_error "genz-gaussian" study dimension --integrand disk
expect_error "plot" study dimension --dims 1 --n 16:32 --runs 2 --plot /nonexistent/d.png
[ ! -e /nonexistent/d.png ] && ok || fail "partial plot left"

# --- importance --------------------------------------------------------------
"$stratum" study importance --runs 4 --samples 2000 >"$tmp/table" && ok || fail "importance table"
grep -q '(b) square light' "$tmp/table" && ok || fail "importance table lacks study (b)"
"$stratum" study importance --runs 8 --samples 4000 --sizes 0.5,4 --distances 1 --json >"$tmp/i.json" && ok \
  || fail "importance --json"
$py - "$tmp/i.json" <<'EOF' && ok || fail "importance JSON contents"
import json, math, sys
data = json.load(open(sys.argv[1]))
sky, lit = data["hemisphere"]
assert sky["scene"] == "sky" and abs(sky["exact"] - math.pi) < 1e-15
assert sky["a"]["method"] == "uniform" and sky["b"]["method"] == "cosine"
assert sky["b"]["variance"] < 1e-25 and abs(sky["b"]["estimate"] - math.pi) < 1e-13   # zero variance
assert abs(sky["a"]["predicted_variance"] - math.pi ** 2 / 3) < 1e-12
assert [(r["size"], r["distance"]) for r in data["light"]] == [(0.5, 1), (4, 1)]
for r in data["light"]:
    assert r["a"]["method"] == "area" and r["b"]["method"] == "solid-angle"
    assert r["variance_ratio"] > 10, r                      # theory: >= 16 for a centred square
    assert abs(r["efficiency_ratio"] - r["variance_ratio"] * r["time_ratio"]) < 1e-9 * r["efficiency_ratio"]
EOF
"$stratum" study importance --runs 2 --samples 500 --plot "$tmp/i.png" >/dev/null && ok || fail "importance --plot"
[ "$(head -c 4 "$tmp/i.png" | od -An -c | tr -d ' ')" = '211PNG' ] && ok || fail "importance plot is not a PNG"

expect_error "invalid runs = 0" study importance --runs 0
expect_error "invalid runs = -2" study importance --runs -2
expect_error "invalid samples = 1" study importance --samples 1
expect_error "invalid size = -1" study importance --sizes 1,-1
expect_error "invalid distance = 0" study importance --distances 0
expect_error "invalid sizes = abc: must be a finite real" study importance --sizes abc
expect_error "plot" study importance --runs 2 --samples 100 --plot /nonexistent/i.png
[ ! -e /nonexistent/i.png ] && ok || fail "partial plot left"
if [ "$(id -u)" != 0 ]; then
  mkdir "$tmp/ro" && chmod 555 "$tmp/ro"
  expect_error "plot" study importance --runs 2 --samples 100 --plot "$tmp/ro/i.png"
  [ -z "$(ls -A "$tmp/ro")" ] && ok || fail "files left in a read-only directory: $(ls -A "$tmp/ro")"
  chmod 755 "$tmp/ro"
fi

# study mis: JSON = Python's columns, the closed form, and the refusals.
"$stratum" study mis --exponents 1,100 --angles 2,30 --runs 4 --samples 64 --seed 2 --json >"$tmp/mis.json" && ok || fail "study mis --json"
if [ -d "$(dirname "$stratum")/../python/stratum" ]; then
PYTHONPATH="$(dirname "$stratum")/../python" /usr/bin/python3 - "$tmp/mis.json" <<'PY' && ok || fail "study mis: CLI = Python"
import json, math, sys
import stratum
d = json.load(open(sys.argv[1]))
py = stratum.study_mis(exponents=[1, 100], angles=[2, 30], runs=4, samples=64, seed=2)
assert len(d["cases"]) == 4 and d["runs"] == 4 and d["samples"] == 64
for k, c in enumerate(d["cases"]):
    assert c["exact"] == py["exact"][k] == -math.expm1((c["exponent"] + 1) * math.log(math.cos(math.radians(c["angle"]))))
    assert [m["method"] for m in c["methods"]] == ["light", "bsdf", "balance", "power"]
    for m in c["methods"]:
        assert m["variance"] == py["variance_" + m["method"]][k] and m["estimate"] == py["estimate_" + m["method"]][k]
PY
else
  echo "skipped: this build has no Python package (the asan preset), so CLI = Python is checked in the release run"
fi
"$stratum" study mis --exponents 10 --angles 10 --runs 2 --samples 8 | grep -q "bal/best" && ok || fail "study mis table"
expect_error "invalid angle = 95" study mis --angles 95
expect_error "invalid samples = 5" study mis --samples 5
expect_error "invalid runs = 1" study mis --runs 1
finish
