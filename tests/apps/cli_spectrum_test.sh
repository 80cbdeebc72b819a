#!/usr/bin/env bash
# CLI tests of `stratum spectrum` and the geometry measures of `stratum
# discrepancy`: closed forms (a regular grid's peaks, P(0) = N), the JSON
# shape, thread independence, the figure, and the bad-input contract
# (message naming the argument, non-zero exit, no partial output file).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3

# An 8x8 grid of cell centres: P = N = 64 at multiples of 8 in both axes, 0
# elsewhere; effective Nyquist (m - 1) / (2m) = 7/16.
"$stratum" spectrum --sampler grid -n 64 -k 20 --json >"$tmp/grid.json" && ok || fail "grid spectrum"
$py - "$tmp/grid.json" <<'PY' && ok || fail "grid spectrum closed form"
import json, sys
d = json.load(open(sys.argv[1]))
k = d["max_frequency"]; side = 2 * k + 1
assert k == 20 and d["n"] == 64 and d["d"] == 2 and len(d["power"]) == side * side
for ky in range(-k, k + 1):
    for kx in range(-k, k + 1):
        p = d["power"][(ky + k) * side + kx + k]
        expected = 64.0 if kx % 8 == 0 and ky % 8 == 0 else 0.0
        assert abs(p - expected) < 1e-9 * 64, (kx, ky, p)
assert abs(d["effective_nyquist"] - 7 / 16) < 1e-12, d["effective_nyquist"]
assert d["radial"]["frequency"][7] == 1.0 and len(d["radial"]["power"]) == k
PY

# Text output: the figures and one row per ring.
"$stratum" spectrum --sampler jittered -n 256 --realizations 4 -k 24 >"$tmp/text" && ok || fail "text spectrum"
grep -q '^effective_nyquist ' "$tmp/text" && grep -q '^oscillation ' "$tmp/text" && ok || fail "text figures: $(head -4 "$tmp/text")"
rows=$(grep -c '^  ' "$tmp/text")
[ "$rows" = 24 ] && ok || fail "24 ring rows, got $rows"

# Same numbers for any thread count; realizations from seeds seed, seed+1, ...
a=$("$stratum" spectrum --sampler random -n 500 --realizations 3 -k 30 --threads 1 --json | md5sum)
b=$("$stratum" spectrum --sampler random -n 500 --realizations 3 -k 30 --threads 2 --json | md5sum)
[ "$a" = "$b" ] && ok || fail "threads change the spectrum"

# Files as realizations; the same points as the sampler gives the same spectrum.
"$stratum" points --sampler random -n 300 -d 2 --seed 5 -o "$tmp/r0.txt" && \
"$stratum" points --sampler random -n 300 -d 2 --seed 6 -o "$tmp/r1.txt" && ok || fail "write point files"
"$stratum" spectrum "$tmp/r0.txt" "$tmp/r1.txt" -k 12 --json >"$tmp/files.json" && ok || fail "spectrum of files"
"$stratum" spectrum --sampler random -n 300 --seed 5 --realizations 2 -k 12 --json >"$tmp/sampler.json" && ok || fail "sampler twin"
$py - "$tmp/files.json" "$tmp/sampler.json" <<'PY' && ok || fail "files equal sampler realizations"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
assert a["realizations"] == 2 and a["n"] == 300
k = 12; side = 2 * k + 1
assert abs(a["power"][k * side + k] - 300) < 1e-9
# text files carry 17 significant digits: the spectra agree closely, not bitwise
assert max(abs(x - y) for x, y in zip(a["power"], b["power"])) < 1e-9
PY

# 1D points.
"$stratum" points --sampler grid -n 10 -d 1 -o "$tmp/line.txt" && "$stratum" spectrum "$tmp/line.txt" -k 25 --json >"$tmp/line.json" && ok || fail "1D spectrum"
$py -c "
import json; d = json.load(open('$tmp/line.json')); p = d['power']
assert d['d'] == 1 and len(p) == 51
assert all(abs(v - (10.0 if (k - 25) % 10 == 0 else 0.0)) < 1e-9 for k, v in enumerate(p))" && ok || fail "1D grid closed form"

# Figure (needs matplotlib): written only on success.
if "$stratum" spectrum --sampler jittered -n 256 -k 20 -o "$tmp/s.png" >/dev/null 2>"$tmp/err"; then
  [ -s "$tmp/s.png" ] && ok || fail "png is empty"
else
  fail "png: $(cat "$tmp/err")"
fi

# Geometry measures through `stratum discrepancy` (the registry).
v=$("$stratum" discrepancy --sampler sobol --randomize none -n 256 -d 2 --measure t-value --json | $py -c 'import json,sys; m=json.load(sys.stdin)["measures"][0]; print(int(m["value"]), int(m["extras"]["m"]))')
[ "$v" = "0 8" ] && ok || fail "sobol 2D t-value 0 with m 8, got $v"
v=$("$stratum" discrepancy --sampler n-rooks -n 50 -d 3 --measure latin --json | $py -c 'import json,sys; print(int(json.load(sys.stdin)["measures"][0]["value"]))')
[ "$v" = 1 ] && ok || fail "n-rooks is Latin, got $v"
v=$("$stratum" discrepancy --sampler grid -n 64 -d 2 --measure min-distance --json | $py -c 'import json,sys; print(json.load(sys.stdin)["measures"][0]["value"])')
[ "$v" = 0.125 ] && ok || fail "grid min distance 1/8, got $v"
expect_error "invalid base = 1" discrepancy --sampler sobol -n 256 -d 2 --measure t-value --measure-param base=1
expect_error "invalid n = 100" discrepancy --sampler sobol -n 100 -d 2 --measure t-value
expect_error "invalid toroidal = 2" discrepancy --sampler random -n 10 -d 2 --measure min-distance --measure-param toroidal=2

# Bad input to spectrum.
expect_error "invalid max-frequency = 0" spectrum --sampler random -n 100 -k 0
expect_error "invalid max-frequency = -5" spectrum --sampler random -n 100 -k -5
expect_error "at most 2^25" spectrum --sampler random -n 100 -k 5000
expect_error "invalid n = 1" spectrum --sampler random -n 1
expect_error "invalid realizations = 0" spectrum --sampler random -n 100 --realizations 0
expect_error "invalid input" spectrum
expect_error "sampler" spectrum --sampler nosuch -n 10
"$stratum" points --sampler random -n 20 -d 3 -o "$tmp/p3.txt"
expect_error "invalid d = 3" spectrum "$tmp/p3.txt"
"$stratum" points --sampler random -n 21 -d 2 -o "$tmp/r21.txt"
expect_error "invalid n of realization 1 = 21" spectrum "$tmp/r0.txt" "$tmp/r21.txt"
printf '0.1 0.2\n0.3 1.5\n' >"$tmp/out.txt"
expect_error "out.txt: line 2, column 2 is 1.5: coordinates must be in \[0, 1\]" spectrum "$tmp/out.txt"
expect_error "invalid max-frequency = 0" spectrum --sampler random -n 100 -k 0 -o "$tmp/bad.png"
[ ! -e "$tmp/bad.png" ] && ok || fail "a failed run left bad.png"

# --- spectrum --image: where a render's error goes ------------------------------------------
scene="$(dirname "${BASH_SOURCE[0]}")/../../scenes/penumbra.json"
"$stratum" render "$scene" --width 64 --height 64 --spp 256 --sampler sobol --seed 9 --quiet -o "$tmp/ref.png" --exr "$tmp/ref.exr" \
  && ok || fail "reference render"
for s in sobol zsobol; do
  "$stratum" render "$scene" --width 64 --height 64 --spp 1 --sampler $s --seed 1 --quiet -o "$tmp/$s.png" --exr "$tmp/$s.exr" \
    && ok || fail "render $s"
  "$stratum" spectrum --image "$tmp/$s.exr" --reference "$tmp/ref.exr" --json >"$tmp/$s.json" && ok || fail "spectrum --image $s"
done
/usr/bin/python3 - "$tmp/sobol.json" "$tmp/zsobol.json" <<'EOF' && ok || fail "image spectra: $(head -c 300 "$tmp/zsobol.json")"
import json, sys
white, blue = (json.load(open(p)) for p in sys.argv[1:3])
assert blue["width"] == 64 and blue["height"] == 64 and len(blue["radial"]["power"]) == 32, blue.keys()
assert abs(blue["radial"]["frequency"][-1] - 0.5) < 1e-12
# one seed each: sobol's low-frequency power scatters with sd ~0.16 around 1.09, zsobol's ~0.04 around 0.25
assert white["low_frequency_power"] > 0.6 and blue["low_frequency_power"] < 0.45, (white["low_frequency_power"], blue["low_frequency_power"])
EOF
"$stratum" spectrum --image "$tmp/zsobol.exr" >"$tmp/text" && grep -q "^low_frequency_power" "$tmp/text" && ok \
  || fail "spectrum --image text: $(head -3 "$tmp/text")"
"$stratum" render "$scene" --width 32 --height 64 --spp 1 --quiet -o "$tmp/small.png" --exr "$tmp/small.exr"
expect_error "must have the image's size 64x64" spectrum --image "$tmp/zsobol.exr" --reference "$tmp/small.exr"
expect_error "measures an image alone" spectrum --image "$tmp/zsobol.exr" -s random -n 16
expect_error "applies only to --image" spectrum -s random -n 16 --reference "$tmp/ref.exr"
expect_error "for --image use --json" spectrum --image "$tmp/zsobol.exr" -o "$tmp/fig.png"
[ ! -e "$tmp/fig.png" ] && ok || fail "a refused --image run wrote its figure"
expect_error "no-such.exr" spectrum --image "$tmp/no-such.exr"

# --- spectrum --frames: where a pixel's error goes in time ----------------------------------
# 16 frames at 1 spp: random's frames are independent (white in time, ~1.0),
# sobol-bn's frames continue each pixel's sequence (blue in time, ~0.43).
for s in random sobol-bn; do
  frames=()
  for k in $(seq 0 15); do
    "$stratum" render "$scene" --width 32 --height 32 --spp 1 --sampler $s --seed 3 --frame $k --quiet \
      -o "$tmp/$s-$k.png" --exr "$tmp/$s-$k.exr" || fail "render $s frame $k"
    frames+=("$tmp/$s-$k.exr")
  done
  "$stratum" spectrum --frames "${frames[@]}" --json >"$tmp/$s-time.json" && ok || fail "spectrum --frames $s"
done
/usr/bin/python3 - "$tmp/random-time.json" "$tmp/sobol-bn-time.json" <<'EOF' && ok || fail "temporal spectra: $(head -c 300 "$tmp/sobol-bn-time.json")"
import json, sys
white, blue = (json.load(open(p)) for p in sys.argv[1:3])
assert blue["width"] == 32 and blue["height"] == 32 and len(blue["frames"]) == 16, blue.keys()
assert blue["temporal"]["frequency"] == [k / 16 for k in range(1, 9)], blue["temporal"]["frequency"]
# the pooled mean of P over k != 0 is 1 by construction (k and 16 - k folded: k = 8 counts once)
p = blue["temporal"]["power"]
assert abs((2 * sum(p[:7]) + p[7]) / 15 - 1) < 1e-12, p
assert white["low_frequency_power"] > 0.75 and blue["low_frequency_power"] < 0.65, (white["low_frequency_power"], blue["low_frequency_power"])
assert blue["lag1_correlation"] < white["lag1_correlation"] - 0.05, (white["lag1_correlation"], blue["lag1_correlation"])
EOF
"$stratum" spectrum --frames "${frames[@]}" >"$tmp/text" && grep -q "^lag1_correlation" "$tmp/text" && ok \
  || fail "spectrum --frames text: $(head -3 "$tmp/text")"
expect_error "needs at least 9 frames" spectrum --frames "${frames[@]:0:8}"
expect_error "every frame must have the size of the first, 32x32" spectrum --frames "${frames[@]:0:9}" "$tmp/small.exr"
expect_error "a reference would cancel" spectrum --frames "${frames[@]}" --reference "$tmp/ref.exr"
expect_error "measures frames alone" spectrum --frames "${frames[@]}" --image "$tmp/zsobol.exr"
expect_error "for --frames use --json" spectrum --frames "${frames[@]}" -o "$tmp/fig.png"

finish
