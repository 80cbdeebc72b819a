#!/usr/bin/env bash
# CLI tests of `stratum compare`: built-in sets, JSON output, equal time,
# variance images and bad input.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"

"$stratum" compare --list | grep -q '^shadow-rays' && ok || fail "compare --list"
"$stratum" compare --builtin shadow-rays --width 8 --height 8 --reference-spp 32 --cache "$tmp/cache" --json >"$tmp/cmp.json" \
  && /usr/bin/python3 -c "
import json; d = json.load(open('$tmp/cmp.json')); rows = d['rows']
assert [r['label'] for r in rows] == ['1 shadow ray', '16 shadow rays'], rows
assert rows[0]['mse_ratio'] == 1 and rows[1]['mse'] > 0 and rows[1]['efficiency'] > 0" && ok || fail "compare --json"
ls "$tmp/cache"/*.exr >/dev/null 2>&1 && ok || fail "reference cached as EXR"
expect_error "comparison" compare --builtin nope
expect_error "reference-spp" compare --reference-spp 0
echo '[{"label": "x", "colour": 2}]' >"$tmp/cfg.json"
expect_error "colour" compare --configs "$tmp/cfg.json" --width 4 --height 4
expect_error "configs" compare --configs "$tmp/nope.json"


# Repeats: paired seeds; the summary is the repeats' mean MSE and median
# seconds, with intervals on the ratios; repeat 0 is the plain comparison.
"$stratum" compare --builtin shadow-rays --width 8 --height 8 --reference-spp 32 --cache "$tmp/cache" --repeats 4 \
  --json >"$tmp/rep.json" && /usr/bin/python3 -c "
import json, math, statistics
one = json.load(open('$tmp/cmp.json'))['rows']; d = json.load(open('$tmp/rep.json')); rows = d['rows']
assert d['repeats'] == 4 and d['confidence'] == 0.95, d
for r, first in zip(rows, one):
    assert len(r['mse_per_seed']) == 4 and len(set(r['mse_per_seed'])) == 4, r
    assert r['mse_per_seed'][0] == first['mse'], (r, first)
    assert math.isclose(r['mse'], statistics.fmean(r['mse_per_seed']), rel_tol=1e-12), r
    assert r['seconds'] == statistics.median(r['seconds_per_seed']), r
low, high = rows[1]['mse_ratio_interval']
ratios = [a / b for a, b in zip(rows[0]['mse_per_seed'], rows[1]['mse_per_seed'])]
assert math.isclose(rows[1]['mse_ratio'], math.exp(statistics.fmean(map(math.log, ratios))), rel_tol=1e-12)
assert 1 < low < rows[1]['mse_ratio'] < high, rows[1]
assert isinstance(rows[1]['time_resolved'], bool)" && ok || fail "compare --repeats 4 --json"
"$stratum" compare --width 8 --height 8 --reference-spp 32 --cache "$tmp/cache" --repeats 3 --confidence 0.9 |
  grep -q "MSE x (90% CI)" && ok || fail "compare --repeats table"
expect_error "invalid repeats = 0" compare --repeats 0 --width 4 --height 4 --cache "$tmp/cache"
expect_error "invalid confidence = 0.9: applies with repeats 2" compare --confidence 0.9 --width 4 --height 4
expect_error "invalid confidence = 1" compare --repeats 2 --confidence 1 --width 4 --height 4

# Equal time: every configuration renders for at least the budget; samples
# are whole passes of its spp; a configuration ~16x costlier per pass
# (64 vs 1 shadow rays) reaches fewer samples in the same time.
echo '[{"label": "cheap", "spp": 4, "light_samples": 1, "sampler": "random", "pixel_centers": true},
       {"label": "costly", "spp": 4, "light_samples": 64, "sampler": "random", "pixel_centers": true}]' >"$tmp/cost.json"
"$stratum" compare --configs "$tmp/cost.json" --width 16 --height 16 --reference-spp 16 --cache "$tmp/cache" \
  --equal-time 0.1 --variance-dir "$tmp/var" --json >"$tmp/eq.json" && /usr/bin/python3 -c "
import json, os; d = json.load(open('$tmp/eq.json')); rows = d['rows']
assert d['equal_time'] == 0.1 and len(rows) == 2, d
for r in rows:
    assert r['seconds'] >= 0.1 and r['passes'] >= 1 and r['spp'] == 4 * r['passes'], r
    assert os.path.getsize(r['variance']) > 0 and r['variance'].startswith('$tmp/var/'), r
assert rows[0]['spp'] > rows[1]['spp'], rows" && ok || fail "compare --equal-time --variance-dir"
"$stratum" compare --width 8 --height 8 --reference-spp 16 --cache "$tmp/cache" --equal-time 0.05 | grep -q "equal time: 0.05 s" \
  && ok || fail "equal-time table"
expect_error "equal-time" compare --equal-time -1 --width 4 --height 4 --cache "$tmp/cache"
touch "$tmp/afile"
expect_error "variance-dir" compare --variance-dir "$tmp/afile/sub" --width 4 --height 4 --reference-spp 4 --cache "$tmp/cache"

# The error's spectrum per row: null for images under 4 pixels a side, a ring per frequency step otherwise.
scene="$(dirname "${BASH_SOURCE[0]}")/../../scenes/penumbra.json"
echo '[{"label": "sobol", "sampler": "sobol", "spp": 1}, {"label": "zsobol", "sampler": "zsobol", "spp": 1},
      {"label": "sobol-bn", "sampler": "sobol-bn", "spp": 1}]' >"$tmp/bn.json"
"$stratum" compare "$scene" --configs "$tmp/bn.json" --width 64 --height 64 --reference-spp 256 --cache "$tmp/cache" --json \
  >"$tmp/bn.out" && /usr/bin/python3 -c "
import json; rows = json.load(open('$tmp/bn.out'))['rows']
assert len(rows[0]['error_spectrum']['power']) == 32 and rows[0]['error_spectrum']['frequency'][0] == 1 / 64, rows[0]
assert rows[0]['low_frequency_power'] > 0.6 and rows[1]['low_frequency_power'] < 0.45, rows
assert rows[2]['low_frequency_power'] < 0.45, rows" && ok || fail "compare error spectra"
"$stratum" compare --builtin shadow-rays --width 3 --height 3 --reference-spp 4 --cache "$tmp/cache" --json \
  | /usr/bin/python3 -c "import json, sys; r = json.load(sys.stdin)['rows'][0]; assert r['low_frequency_power'] is None, r" \
  && ok || fail "compare on a 3x3 image gives a spectrum"
"$stratum" compare "$scene" --configs "$tmp/bn.json" --width 64 --height 64 --reference-spp 256 --cache "$tmp/cache" \
  | grep -q "low-f" && ok || fail "compare table lacks the low-f column"

finish
