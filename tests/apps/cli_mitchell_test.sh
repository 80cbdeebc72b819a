#!/usr/bin/env bash
# CLI tests of the edge measures (through `stratum discrepancy`) and of
# `stratum study mitchell`: values, JSON shape, determinism across threads,
# the figure, and the bad-input contract (message naming the argument,
# non-zero exit, no partial output file).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3

# Exact edge discrepancy of all points at the centre: every line through it halves the square, D = 1/2.
printf '0.5 0.5\n0.5 0.5\n0.5 0.5\n' >"$tmp/centre.txt"
"$stratum" discrepancy "$tmp/centre.txt" --measure edge --json >"$tmp/centre.json" && ok || fail "edge on a file"
$py -c "import json; m=json.load(open('$tmp/centre.json'))['measures'][0]; assert m['kind']=='exact' and abs(m['value']-0.5)<1e-15, m" \
  && ok || fail "edge of the centre points is 1/2"

# Random-edge: RMS, mean and max, max <= exact, deterministic across threads and seeded.
"$stratum" discrepancy --sampler jittered -n 256 -d 2 --seed 2 --measure edge --json >"$tmp/exact.json" && ok || fail "edge json"
"$stratum" discrepancy --sampler jittered -n 256 -d 2 --seed 2 --measure edge-random --measure-param lines=4000 --measure-param seed=9 --json \
  >"$tmp/random.json" && ok || fail "edge-random json"
$py - "$tmp/exact.json" "$tmp/random.json" <<'PY' && ok || fail "edge-random extras and bound"
import json, sys
exact = json.load(open(sys.argv[1]))["measures"][0]
random = json.load(open(sys.argv[2]))["measures"][0]
assert random["kind"] == "estimate" and random["extras"]["lines"] == 4000, random
assert random["extras"]["mean"] <= random["value"] <= random["extras"]["max"] <= exact["value"] + 1e-12, (random, exact)
PY
a=$("$stratum" discrepancy --sampler random -n 500 -d 2 --measure edge-random --measure-param lines=3000 --threads 1)
b=$("$stratum" discrepancy --sampler random -n 500 -d 2 --measure edge-random --measure-param lines=3000 --threads 2)
[ "$a" = "$b" ] && ok || fail "threads change edge-random: $a / $b"
c=$("$stratum" discrepancy --sampler random -n 500 -d 2 --measure edge-random --measure-param lines=3000 --measure-param seed=1)
[ "$a" != "$c" ] && ok || fail "the seed of the lines changes nothing"

expect_error "invalid d = 3" discrepancy --sampler random -n 10 -d 3 --measure edge
expect_error "invalid d = 1" discrepancy --sampler random -n 10 -d 1 --measure edge-random
expect_error "invalid lines = 0" discrepancy --sampler random -n 10 -d 2 --measure edge-random --measure-param lines=0
expect_error "invalid lines = -4" discrepancy --sampler random -n 10 -d 2 --measure edge-random --measure-param lines=-4
expect_error "invalid lines = many" discrepancy --sampler random -n 10 -d 2 --measure edge-random --measure-param lines=many
expect_error "invalid seed = -1" discrepancy --sampler random -n 10 -d 2 --measure edge-random --measure-param seed=-1
expect_error "invalid measure-param = lines=5: edge takes no parameters" discrepancy --sampler random -n 10 -d 2 --measure edge --measure-param lines=5
printf '0.5 0.5\n0.2 1.5\n' >"$tmp/outside.txt"
expect_error "outside.txt: line 2, column 2 is 1.5: coordinates must be in \[0, 1\]" discrepancy "$tmp/outside.txt" --measure edge

# The study: text table, JSON, determinism across threads, the figure.
"$stratum" study mitchell --counts 16,100 --realizations 4 --lines 500 >"$tmp/table.txt" && ok || fail "study text"
grep -q '^Zaremba ' "$tmp/table.txt" && grep -q '^random ' "$tmp/table.txt" && grep -q 'N = 100' "$tmp/table.txt" \
  && ok || fail "study table rows: $(cat "$tmp/table.txt")"
"$stratum" study mitchell --counts 16,100 --realizations 4 --lines 500 --json --threads 1 >"$tmp/s1.json" && ok || fail "study json"
"$stratum" study mitchell --counts 16,100 --realizations 4 --lines 500 --json --threads 2 >"$tmp/s2.json" && ok || fail "study json 2"
cmp -s "$tmp/s1.json" "$tmp/s2.json" && ok || fail "threads change the study"
$py - "$tmp/s1.json" <<'PY' && ok || fail "study json shape"
import json, sys
data = json.load(open(sys.argv[1]))
assert data["study"] == "mitchell" and data["counts"] == [16, 100] and data["realizations"] == 4
names = [p["sampler"] for p in data["patterns"]]
assert names == ["zaremba", "jittered", "poisson-disk", "n-rooks", "random"], names
for p in data["patterns"]:
    assert [c["n"] for c in p["cells"]] == [16, 100]  # 100 = 10^2 suits jittered too
    assert all(c["rms_se"] >= 0 and c["mean"] <= c["rms"] <= c["max"] for c in p["cells"])
    assert p["spectrum"]["n"] == 100 and len(p["spectrum"]["power"]) > 0
assert data["notes"] == []
PY
"$stratum" study mitchell --counts 20 --realizations 2 --lines 100 --json >"$tmp/s3.json" && ok || fail "study with 20"
$py -c "
import json; d = json.load(open('$tmp/s3.json'))
j = [p for p in d['patterns'] if p['sampler'] == 'jittered'][0]['cells'][0]
assert j['requested'] == 20 and j['n'] == 16, j
assert any('jittered: 16 points instead of 20' in n for n in d['notes']), d['notes']" && ok || fail "nearest valid count"
"$stratum" study mitchell --counts 16,64 --realizations 2 --lines 200 --plot "$tmp/m.png" >/dev/null && ok || fail "plot"
$py -c "import matplotlib.image as i; a=i.imread('$tmp/m.png'); assert a.shape[0] > 300 and a.shape[1] > 800, a.shape" \
  && ok || fail "figure size"

expect_error "invalid lines = 0" study mitchell --counts 16 --lines 0
expect_error "invalid realizations = 0" study mitchell --counts 16 --realizations 0
expect_error "invalid counts = 1" study mitchell --counts 16,1
expect_error "invalid threads = -2" study mitchell --counts 16 --threads -2
expect_error "counts" study mitchell --counts 16,abc
expect_error "invalid lines = 0" study mitchell --counts 16 --lines 0 --plot "$tmp/bad.png"
[ ! -e "$tmp/bad.png" ] && ok || fail "a failed study left a figure"

# Extra patterns (--sampler): one more row each; Mitchell's five rows are unchanged by them.
"$stratum" study mitchell --counts 16,64 --realizations 2 --lines 200 --seed 3 >"$tmp/five.txt" && ok || fail "five"
"$stratum" study mitchell --counts 16,64 --realizations 2 --lines 200 --seed 3 --sampler sobol:owen --sampler halton \
  >"$tmp/seven.txt" && ok || fail "extras"
grep -q '^sobol:owen ' "$tmp/seven.txt" && grep -q '^halton ' "$tmp/seven.txt" && ok || fail "extra rows: $(cat "$tmp/seven.txt")"
[ "$(tail -n +3 "$tmp/seven.txt" | grep -c '+-')" = 7 ] && ok || fail "seven rows"
diff <(grep -E '^(Zaremba|jittered|Poisson|N-rooks|random) ' "$tmp/five.txt") \
     <(grep -E '^(Zaremba|jittered|Poisson|N-rooks|random) ' "$tmp/seven.txt") >/dev/null && ok || fail "extras changed the five rows"
expect_error "sampler" study mitchell --counts 16 --sampler no-such
expect_error "randomizer" study mitchell --counts 16 --sampler sobol:no-such
expect_error "jittered" study mitchell --counts 16 --sampler jittered

finish
