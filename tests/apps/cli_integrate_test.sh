#!/usr/bin/env bash
# CLI tests of `stratum integrate` and `stratum converge`: values against the
# exact integrals, JSON shape, the figure, and the bad-input contract (message
# naming the argument, non-zero exit, no partial output file).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3

"$stratum" integrate --list | grep -q '^genz-corner-peak ' && ok || fail "integrate --list names genz-corner-peak"
"$stratum" integrate --list --json | $py -c 'import json,sys; d=json.load(sys.stdin)["integrands"]; assert {"disk","step","edge-random"} <= {e["name"] for e in d}' \
  && ok || fail "integrate --list --json"

# disk with 8 Owen-scrambled Sobol replicates: |error| below 5.4 standard errors (t_7, α = 2e-4), exact 1/2.
"$stratum" integrate --integrand disk --sampler sobol:owen -n 4096 --runs 8 --json >"$tmp/i.json" && ok || fail "integrate disk"
$py -c "import json; r=json.load(open('$tmp/i.json')); assert r['exact']==0.5 and r['runs']==8 and len(r['run_estimates'])==8; assert abs(r['error'])<5.4*r['standard_error'], r; assert r['randomize']=='owen'" \
  && ok || fail "integrate disk values"
# Genz Gaussian in d = 3 with parameters: one random point set, z-test at 4 standard errors.
"$stratum" integrate --integrand genz-gaussian -d 3 --integrand-param a=2,3,4 --integrand-param u=0.2 --sampler random -n 20000 --seed 5 --json >"$tmp/g.json" \
  && ok || fail "integrate genz-gaussian"
$py -c "
import json, math
r = json.load(open('$tmp/g.json'))
exact = math.prod(math.sqrt(math.pi)/(2*a)*(math.erf(a*0.8)+math.erf(a*0.2)) for a in (2,3,4))
assert abs(r['exact']-exact) < 1e-14 and r['d'] == 3 and r['standard_error_kind'] == 'iid', r
assert abs(r['error']) < 4*r['standard_error'], r" && ok || fail "genz-gaussian exact and error"
# Runs that do not differ give no standard error (never a false 0); Hammersley's i/N is randomized.
"$stratum" integrate --integrand step -s hammersley:owen -n 64 --runs 16 --json >"$tmp/h.json" && ok || fail "integrate hammersley:owen"
$py -c "import json; r=json.load(open('$tmp/h.json')); assert r['standard_error'] > 0 and abs(r['error']) < 4.07*r['standard_error'], r" \
  && ok || fail "hammersley:owen standard error"
"$stratum" integrate --integrand step -s grid -n 64 --runs 16 >"$tmp/out" && ok || fail "integrate grid"
grep -q '^standard error  unavailable: the 16 runs gave identical estimates (grid:none' "$tmp/out" && ok || fail "grid: $(cat "$tmp/out")"
"$stratum" integrate --integrand step -s zaremba -n 64 --runs 4 --json >"$tmp/z.json" && ok || fail "integrate zaremba"
$py -c "import json; r=json.load(open('$tmp/z.json')); assert r['standard_error'] is None and r['standard_error_kind'] == 'identical-runs', r" \
  && ok || fail "zaremba: standard_error null"
# The RQMC interval and the efficiency: t_{7, 0.975} = 2.3646 standard errors by default, t_{7, 0.95} at --confidence 0.9.
"$stratum" integrate --integrand gaussian -s random -n 64 --runs 8 --seed 2 --confidence 0.9 --json >"$tmp/t.json" && ok || fail "integrate --confidence"
$py -c "
import json; r = json.load(open('$tmp/t.json'))
assert r['confidence'] == 0.9 and abs(r['half_width'] - 1.8945786050900074 * r['standard_error']) < 1e-12 * r['standard_error'], r
assert abs(r['interval'][0] - (r['estimate'] - r['half_width'])) < 1e-15 and abs(r['interval'][1] - (r['estimate'] + r['half_width'])) < 1e-15
assert abs(r['efficiency'] * r['standard_error']**2 * 8 * r['seconds_per_run'] - 1) < 1e-9, r" && ok || fail "interval and efficiency values"
"$stratum" integrate --integrand gaussian -s random -n 64 --runs 8 >"$tmp/out" && ok || fail "integrate text"
grep -q '^95% interval \[.*Student-t over 8 runs' "$tmp/out" && grep -q '^efficiency ' "$tmp/out" && ok || fail "text interval: $(cat "$tmp/out")"
expect_error "invalid confidence = 1.5: must be a level strictly between 0 and 1" integrate --integrand disk -n 10 --confidence 1.5
expect_error "invalid confidence = 0" integrate --integrand disk -n 10 --confidence 0
"$stratum" integrate --integrand step --sampler random -n 1000 | grep -q '^exact *0.3183098861837906' && ok || fail "text output"

# converge: JSON shape, thread invariance, the slope of random sampling near -1.
"$stratum" converge --integrand gaussian --samplers random,jittered --n 16:4096:4 --runs 32 --threads 1 --json >"$tmp/c1.json" && ok || fail "converge"
"$stratum" converge --integrand gaussian --samplers random,jittered --n 16:4096:4 --runs 32 --threads 2 --json >"$tmp/c2.json" && ok || fail "converge threads 2"
$py -c "
import json
a, b = json.load(open('$tmp/c1.json')), json.load(open('$tmp/c2.json'))
for s, t in zip(a['samplers'], b['samplers']):
    assert [r['variance'] for r in s['rows']] == [r['variance'] for r in t['rows']]
    assert [r['n'] for r in s['rows']] == [16, 64, 256, 1024, 4096]
r, j = a['samplers']
assert abs(r['slope'] + 1) < 4 * max(r['slope_standard_error'], 0.05), r['slope']
assert abs(j['slope'] + 2) < 4 * max(j['slope_standard_error'], 0.05), j['slope']
lo, hi = r['slope_interval']
assert lo < r['slope'] < hi and r['slope_confidence'] == 0.95 and r['slope_sampling_standard_error'] > 0
assert lo <= -1 <= hi, (lo, hi)  # the jackknife interval holds the true rate (seed 0)" && ok || fail "converge values"
"$stratum" converge --integrand genz-gaussian -d 4 --samplers random --n 64:16384:4 --runs 32 --seed 1 --confidence 0.9 \
  >"$tmp/out" && ok || fail "converge --confidence"
grep -q '^random:none  slope of log variance vs log N: -0.987, 90% interval \[-1.1[0-9][0-9], -0.8[0-9][0-9]\]' "$tmp/out" \
  && ok || fail "converge prints the interval: $(sed -n 3p "$tmp/out")"
expect_error "invalid confidence = 1" converge --integrand gaussian --samplers random --n 16,64 --runs 4 --confidence 1
"$stratum" converge --integrand bilinear --samplers sobol:owen-hash,random --n 64,256,1024 --runs 8 --plot "$tmp/c.png" >"$tmp/out" && ok || fail "converge --plot"
$py -c "import sys; sys.exit(open('$tmp/c.png','rb').read(8) != b'\x89PNG\r\n\x1a\n')" && ok || fail "plot is a PNG"
grep -q 'sobol:owen-hash  slope' "$tmp/out" && ok || fail "table names the sampler and its slope"

expect_error "invalid n = 0" integrate --integrand disk -n 0
expect_error "invalid n = -5" integrate --integrand disk -n -5
expect_error "invalid n = (missing)" integrate --integrand disk
expect_error "invalid integrand = nosuch" integrate --integrand nosuch -n 10
expect_error "invalid sampler = nosuch" integrate --integrand disk --sampler nosuch -n 10
expect_error "invalid d = 3" integrate --integrand disk -n 10 -d 3
expect_error "invalid a\[0] = x: must be a finite real in (0, inf)" integrate --integrand genz-gaussian -n 10 --integrand-param a=x
expect_error "invalid integrand-param = bogus=1: genz-gaussian takes a, u" integrate --integrand genz-gaussian -n 10 --integrand-param bogus=1
expect_error "invalid randomize = owen" integrate --integrand disk --sampler random --randomize owen -n 10
expect_error "invalid runs = 0" integrate --integrand disk -n 10 --runs 0
# The default --n works for every integrand and sampler pair of the registry's
# integrands with random and jittered: jittered (2D) skips the non-squares and says so.
integrands=$("$stratum" integrate --list --json | $py -c 'import json,sys; print(" ".join(e["name"] for e in json.load(sys.stdin)["integrands"]))')
[ "$(echo "$integrands" | wc -w)" -ge 5 ] && ok || fail "integrate --list --json: integrands '$integrands'"  # an empty listing must not pass
for integrand in $integrands; do
  "$stratum" converge --integrand "$integrand" --samplers random,jittered --runs 2 --json >"$tmp/d.json" && ok || fail "converge default --n for $integrand"
done
$py -c "
import json; j = json.load(open('$tmp/d.json'))['samplers']
assert j[0]['skipped'] == [] and len(j[0]['rows']) == 13, j[0]
assert [r['n'] for r in j[1]['rows']] == [16, 64, 256, 1024, 4096, 16384, 65536], j[1]['rows']
assert [s['n'] for s in j[1]['skipped']] == [32, 128, 512, 2048, 8192, 32768] and 'invalid n = 32' in j[1]['skipped'][0]['reason']" \
  && ok || fail "converge default --n skips listed"
"$stratum" converge --integrand disk --samplers random,jittered --runs 2 >"$tmp/out" && ok || fail "converge disk default --n"
grep -q '^skipped N = 32,128,512,2048,8192,32768 of the default --n' "$tmp/out" && ok || fail "converge table says what it skipped"
expect_error "invalid n = 16:100" converge --integrand disk --samplers random --n 16:100
expect_error "invalid n = 64:16" converge --integrand disk --samplers random --n 64:16
expect_error "invalid n = 16,8" converge --integrand disk --samplers random --n 16,8
expect_error "invalid n = 0:16" converge --integrand disk --samplers random --n 0:16
expect_error "invalid n = 32: equal strata" converge --integrand disk --samplers jittered --n 16:64
expect_error "invalid runs = 1" converge --integrand disk --samplers random --runs 1
expect_error "invalid sampler = nosuch" converge --integrand disk --samplers random,nosuch
expect_error "invalid integrand = nosuch" converge --integrand nosuch --samplers random
expect_error "invalid threads = 1025" converge --integrand disk --samplers random --threads 1025
expect_error "plot" converge --integrand disk --samplers random --n 16:64 --runs 4 --plot /nonexistent/c.png
[ ! -e /nonexistent/c.png ] && ok || fail "partial plot left"
if [ "$(id -u)" != 0 ]; then
  mkdir "$tmp/ro" && chmod 555 "$tmp/ro"
  expect_error "plot" converge --integrand disk --samplers random --n 16:64 --runs 4 --plot "$tmp/ro/c.png"
  [ -z "$(ls -A "$tmp/ro")" ] && ok || fail "files left in a read-only directory"
  chmod 755 "$tmp/ro"
fi
[ -z "$(ls -A "$tmp" | grep -v -e '^out$' -e '^err$' -e '\.json$' -e '^c\.png$' -e '^ro$')" ] && ok || fail "stray files: $(ls -A "$tmp")"

# To a tolerance: the steps double n and stop at the first half-width within the target; JSON = text.
"$stratum" integrate --integrand genz-gaussian -d 3 -s sobol:owen -n 16 --runs 8 --abs-tol 1e-4 --json >"$tmp/tol.json" && ok || fail "integrate --abs-tol"
/usr/bin/python3 - "$tmp/tol.json" <<'PY' && ok || fail "tolerance JSON"
import json, sys
d = json.load(open(sys.argv[1]))
t = d["tolerance"]
assert t["met"] and t["abs_tol"] == 1e-4 and t["target"] == 1e-4
steps = t["steps"]
assert [s["n"] for s in steps] == [16 << k for k in range(len(steps))]
assert all(s["half_width"] > 1e-4 for s in steps[:-1]) and steps[-1]["half_width"] <= 1e-4
assert d["n"] == steps[-1]["n"] and d["half_width"] == steps[-1]["half_width"]
PY
"$stratum" integrate --integrand gaussian -s random -n 16 --runs 4 --abs-tol 1e-9 --max-n 64 | grep -q "NOT met (max-n reached).*n = 16, 32, 64" && ok || fail "tolerance not met at max-n"
expect_error "invalid abs-tol = 0: give --abs-tol or --rel-tol" integrate --integrand gaussian -n 16 --runs 4 --abs-tol 0
expect_error "invalid rel-tol = 1" integrate --integrand gaussian -n 16 --runs 4 --rel-tol 1
expect_error "invalid max-n = 64: applies only with a tolerance, abs-tol or rel-tol" integrate --integrand gaussian -n 16 --runs 4 --max-n 64
expect_error "which grid refuses" integrate --integrand gaussian -s grid:cp -n 16 --runs 4 --abs-tol 1e-3
expect_error "gives no error estimate" integrate --integrand gaussian -s sobol:none -n 16 --runs 4 --abs-tol 1e-3
finish
