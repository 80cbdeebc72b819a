#!/usr/bin/env bash
# CLI tests of `stratum discrepancy --measure star`: exact values against
# closed forms (Hammersley, De Clerck 1986; 1D, Niederreiter 1992 Thm 2.6),
# bounds bracketing the exact value, and the bad-input contract.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3

# Hammersley, N = 2^10: N·D* = m/3 + 13/9 − (−1)^m·4/(9·2^m).
"$stratum" discrepancy --sampler hammersley -n 1024 -d 2 --randomize none --measure star --json >"$tmp/h.json" \
  && ok || fail "hammersley star"
$py - "$tmp/h.json" <<'EOF' && ok || fail "hammersley closed form"
import json, sys
r = json.load(open(sys.argv[1]))["measures"][0]
m, n = 10, 1024
expected = (m / 3 + 13 / 9 - 4 / (9 * n)) / n
assert r["name"] == "star" and r["kind"] == "exact", r
assert abs(r["value"] - expected) < 1e-14, (r["value"], expected)
EOF

# A 1D file: the closed form computed here.
$py -c "
import random
random.seed(5)
print('\n'.join(repr(random.random()) for _ in range(37)))" >"$tmp/x1.txt"
got=$("$stratum" discrepancy "$tmp/x1.txt" --measure star --json)
$py - "$tmp/x1.txt" "$got" <<'EOF' && ok || fail "1D closed form"
import json, sys
x = sorted(float(v) for v in open(sys.argv[1]).read().split())
n = len(x)
expected = 1 / (2 * n) + max(abs(v - (2 * i + 1) / (2 * n)) for i, v in enumerate(x))
r = json.loads(sys.argv[2])["measures"][0]
assert r["kind"] == "exact" and abs(r["value"] - expected) < 1e-15, (r, expected)
EOF

# Bounds bracket the exact value; auto falls back to bounds beyond the exact limit.
exact=$("$stratum" discrepancy --sampler random -n 300 -d 3 --seed 4 --measure star --json)
bounds=$("$stratum" discrepancy --sampler random -n 300 -d 3 --seed 4 --measure star --measure-param method=bounds --measure-param delta=0.05 --json)
$py - "$exact" "$bounds" <<'EOF' && ok || fail "bounds bracket the exact value"
import json, sys
e = json.loads(sys.argv[1])["measures"][0]
b = json.loads(sys.argv[2])["measures"][0]
assert e["kind"] == "exact" and b["kind"] == "bounds", (e, b)
assert b["lower"] <= e["value"] <= b["upper"], (b, e)
assert b["upper"] - b["lower"] <= 0.05 + 1e-12 and b["extras"]["delta"] == 0.05, b
EOF
"$stratum" discrepancy --sampler random -n 300 -d 7 --measure star | grep -q '^star *in \[' && ok \
  || fail "d = 7 reports bounds as an interval"

# Threads do not change the result.
a=$("$stratum" discrepancy --sampler random -n 5000 -d 2 --seed 2 --measure star --threads 1)
b=$("$stratum" discrepancy --sampler random -n 5000 -d 2 --seed 2 --measure star --threads 2)
[ "$a" = "$b" ] && ok || fail "threads change the star discrepancy: $a vs $b"

# Bad input.
expect_error "invalid d = 7" discrepancy --sampler random -n 300 -d 7 --measure star --measure-param method=exact
expect_error "method=bounds" discrepancy --sampler random -n 300 -d 7 --measure star --measure-param method=exact
expect_error "invalid method = fast" discrepancy --sampler random -n 10 --measure star --measure-param method=fast
expect_error "invalid delta = 2" discrepancy --sampler random -n 10 --measure star --measure-param method=bounds --measure-param delta=2
expect_error "invalid measure-param = lines=5: star takes method, delta, max_boxes" discrepancy --sampler random -n 10 --measure star --measure-param lines=5
expect_error "invalid max_boxes = 0" discrepancy --sampler random -n 10 --measure star --measure-param max_boxes=0
printf '0.5 0.5\n' >"$tmp/one.txt"
expect_error "invalid n = 1" discrepancy "$tmp/one.txt" --measure star
printf '0.5 0.5\n0.25 1.5\n' >"$tmp/out.txt"
expect_error "out.txt: line 2, column 2 is 1.5: coordinates must be in \[0, 1\]" discrepancy "$tmp/out.txt" --measure star
printf '0.5 nan\n0.25 0.5\n' >"$tmp/nan.txt"
expect_error "invalid" discrepancy "$tmp/nan.txt" --measure star

finish
